; A corridor p1 p2 p3 p4 p5 (left to right): the player at p1, a stone at p3, the goal p5.
; The player walks to p2 (free) and pushes twice (p3 -> p4, p4 -> p5): cost 2, 3 steps.
; A plan that walks back and forth costs the same: only pushes cost.
(define (problem sokoban-corridor)
  (:domain sokoban)
  (:objects left right - direction me - player box - stone p1 p2 p3 p4 p5 - location)
  (:init (at me p1) (at box p3) (clear p2) (clear p4) (clear p5)
         (is-nongoal p1) (is-nongoal p2) (is-nongoal p3) (is-nongoal p4) (is-goal p5)
         (move-dir p1 p2 right) (move-dir p2 p3 right) (move-dir p3 p4 right) (move-dir p4 p5 right)
         (move-dir p2 p1 left) (move-dir p3 p2 left) (move-dir p4 p3 left) (move-dir p5 p4 left)
         (= (total-cost) 0))
  (:goal (at-goal box))
  (:metric minimize (total-cost)))
