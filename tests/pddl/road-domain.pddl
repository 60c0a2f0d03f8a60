; Driving on roads whose lengths are static costs in the problem's :init.
(define (domain road)
  (:requirements :typing :action-costs)
  (:types place)
  (:predicates (at ?p - place) (road ?from ?to - place))
  (:functions (road-length ?from ?to - place) - number (total-cost) - number)
  (:action drive
    :parameters (?from ?to - place)
    :precondition (and (at ?from) (road ?from ?to))
    :effect (and (not (at ?from)) (at ?to) (increase (total-cost) (road-length ?from ?to)))))
