; Bring the paper from home to the office and the dictionary from the office home, with
; the briefcase back home: put-in paper, move home office, take-out paper, put-in dict,
; move office home, take-out dict = 6 steps; no shorter plan (each object needs a put-in
; and a take-out, and the briefcase must go there and back).
(define (problem briefcase-1)
  (:domain briefcase)
  (:objects office - location paper dict - portable)
  (:init (is-at home) (at paper home) (at dict office))
  (:goal (and (at paper office) (at dict home) (is-at home)
              (forall (?x - portable) (not (in ?x))))))
