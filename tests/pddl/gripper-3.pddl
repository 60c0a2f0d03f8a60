; Three balls from room a to room b. By hand: pick two (2), move (1), drop two (2),
; move back (1), pick the third (1), move (1), drop it (1): 9 steps, and no plan is
; shorter (each ball needs a pick and a drop, 6, and the robot must cross a->b, b->a, a->b).
(define (problem gripper-3)
  (:domain gripper-typed)
  (:objects rooma roomb - room ball1 ball2 ball3 - ball)
  (:init (at-robby rooma) (free left) (free right) (at ball1 rooma) (at ball2 rooma) (at ball3 rooma))
  (:goal (and (at ball1 roomb) (at ball2 roomb) (at ball3 roomb))))
