; Five cells in a row, heaps on c1 and c5, the agent on c3 holding nothing; c2 and c4
; must be built. By hand: both heaps must be dug (each build spends one, each heap gives
; one), so both ends are visited: at least 2 moves to the nearer end and 4 across. The
; second dig is at an end, and the build beside it needs a count: the first dig's count
; is spent at the other end's neighbour on the way across (c3 c2 c1, dig, c2 build, c3
; c4 c5, dig) or kept, and either way the last build (c4 after c5, or c2 after c1)
; takes one move back: 7 moves, 2 digs, 2 builds = 11, and no plan is shorter.
(define (problem stock-1)
  (:domain stock)
  (:objects r - agent c1 c2 c3 c4 c5 - cell n0 n1 n2 - num)
  (:init (at r c3) (has r n0) (succ n0 n1) (succ n1 n2) (heap c1) (heap c5)
         (next c1 c2) (next c2 c1) (next c2 c3) (next c3 c2) (next c3 c4) (next c4 c3) (next c4 c5) (next c5 c4))
  (:goal (and (built c2) (built c4))))
