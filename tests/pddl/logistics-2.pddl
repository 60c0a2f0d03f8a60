; One package from a house in city 1 to a house in city 2. By hand: load into truck1,
; drive to airport1, unload, load into the plane, fly, unload, load into truck2 (already
; at airport2), drive to house2, unload: 9 steps; every step is forced (the package must
; ride truck1, the plane and truck2: 3 loads + 3 unloads, plus one drive, one flight, one drive).
(define (problem logistics-2)
  (:domain logistics)
  (:objects city1 city2 - city house1 house2 - location airport1 airport2 - airport
            truck1 truck2 - truck plane - airplane pkg - package)
  (:init (in-city house1 city1) (in-city airport1 city1) (in-city house2 city2) (in-city airport2 city2)
         (at truck1 house1) (at truck2 airport2) (at plane airport1) (at pkg house1))
  (:goal (at pkg house2)))
