; Twenty spare tokens, two in hand; a token must lie on c2 and one on c4. By hand: the
; agent must stand on c2 and on c4 (at least 3 moves from c1) and place twice: move,
; place, move, move, place = 5, and no plan is shorter.
(define (problem tokens-1)
  (:domain tokens)
  (:objects c1 c2 c3 c4 - cell n0 n1 n2 - num
            t1 t2 t3 t4 t5 t6 t7 t8 t9 t10 t11 t12 t13 t14 t15 t16 t17 t18 t19 t20 - token)
  (:init (at c1) (next c1 c2) (next c2 c1) (next c2 c3) (next c3 c2) (next c3 c4) (next c4 c3)
         (has n2) (succ n0 n1) (succ n1 n2))
  (:goal (and (exists (?t - token) (on ?t c2)) (exists (?t - token) (on ?t c4)))))
