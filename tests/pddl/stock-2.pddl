; The stock domain with a goal of holding at least two (any of the counts n2, n3): heaps
; on c1, c2 and c5, the agent on c3 holding nothing. By hand: only dig raises the count,
; once per heap, so two digs on two heaps; the agent stands on no heap and heaps are
; apart, so at least one move before the first dig and one between them: c3 c2, dig,
; c2 c1, dig = 4, and no plan is shorter.
(define (problem stock-2)
  (:domain stock)
  (:objects r - agent c1 c2 c3 c4 c5 - cell n0 n1 n2 n3 - num)
  (:init (at r c3) (has r n0) (succ n0 n1) (succ n1 n2) (succ n2 n3) (heap c1) (heap c2) (heap c5)
         (next c1 c2) (next c2 c1) (next c2 c3) (next c3 c2) (next c3 c4) (next c4 c3) (next c4 c5) (next c5 c4))
  (:goal (or (has r n2) (has r n3))))
