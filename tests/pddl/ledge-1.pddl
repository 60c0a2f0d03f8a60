; Four cells on solid ground (level l0); the agent stands on c1 at level l1 holding one
; block; c4 must be marked at level l2, which only an agent at level l2 on c3 can do.
; By hand: being at level l2 takes a climb, onto c3 (the only cell beside c4) or onto a
; cell from which c3 is then walked to at level l2; either way a block must first stand
; one level below the agent's cell at l1, put from a neighbouring cell. From c1 the agent
; can put only onto c2, and climbing onto c2 leaves c3 without the block it would need
; to be walked onto at level l2. So: walk c1 c2, put onto c3 at l1, climb onto c3, mark
; c4 at l2 = 4 steps, and no plan is shorter (mark, climb and put are each needed, and
; the put must be made from c2 or c4, which the agent reaches only by walking).
(define (problem ledge-1)
  (:domain ledge)
  (:objects r - agent c1 c2 c3 c4 - cell l0 l1 l2 - level)
  (:init (at r c1) (lvl r l1) (holding r)
         (next c1 c2) (next c2 c1) (next c2 c3) (next c3 c2) (next c3 c4) (next c4 c3)
         (up l0 l1) (up l1 l2)
         (solid c1 l0) (solid c2 l0) (solid c3 l0) (solid c4 l0))
  (:goal (marked c4 l2)))
