; a -> c directly costs 10; a -> b -> c costs 1 + 1 = 2, the optimum (two steps).
(define (problem road-1)
  (:domain road)
  (:objects a b c - place)
  (:init (at a) (road a c) (road a b) (road b c)
         (= (road-length a c) 10) (= (road-length a b) 1) (= (road-length b c) 1)
         (= (total-cost) 0))
  (:goal (at c))
  (:metric minimize (total-cost)))
