(define (domain broken)
  (:requirements :strips)
  (:predicates (p))
  (:action a
    :parameters ()
    :precondition (and (p)
    :effect (not (p))))
