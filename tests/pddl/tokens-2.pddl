; As tokens-1, but t7 (named by the goal, so not interchangeable) must lie on c4, and
; one token already lies on c3 (t20: not free, so not interchangeable with the others
; either). By hand: c2 and c4 must be visited (3 moves), two tokens placed (2): 5; t7
; can be placed on c4 last, so no detour is needed: 5.
(define (problem tokens-2)
  (:domain tokens)
  (:objects c1 c2 c3 c4 - cell n0 n1 n2 - num
            t1 t2 t3 t4 t5 t6 t7 t8 t9 t10 t11 t12 t13 t14 t15 t16 t17 t18 t19 t20 - token)
  (:init (at c1) (next c1 c2) (next c2 c1) (next c2 c3) (next c3 c2) (next c3 c4) (next c4 c3)
         (has n2) (succ n0 n1) (succ n1 n2) (placed t20) (on t20 c3))
  (:goal (and (exists (?t - token) (on ?t c2)) (on t7 c4))))
