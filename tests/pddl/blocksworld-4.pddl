; Reverse a tower: d on c on b on a  ->  a on b on c on d. By hand: unstack d, put it
; down, unstack c, stack it on d, unstack b, stack it on c, pick up a, stack it on b: 8.
; Lower bound: a, b and c each need a pick and a stack (6), and d sits on c, so d must be
; unstacked and put somewhere first (2 more; it cannot be stacked on c, b or a usefully,
; all three still have to move): 8.
(define (problem blocksworld-4)
  (:domain blocksworld)
  (:objects a b c d - block)
  (:init (ontable a) (on b a) (on c b) (on d c) (clear d) (handempty))
  (:goal (and (on a b) (on b c) (on c d))))
