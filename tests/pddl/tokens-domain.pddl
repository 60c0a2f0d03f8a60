; Tokens put down on a row of cells (written for bcc's tests of the lifted search). The
; agent carries a count of tokens (num, with succ); a token object is used by `place`
; only while not placed. Tokens no goal names are interchangeable: the lifted search
; tries the first free one only (pddl_io/lifted_states.py, Symmetry).
(define (domain tokens)
  (:requirements :typing :negative-preconditions :existential-preconditions)
  (:types cell token num)
  (:predicates (at ?c - cell) (next ?a ?b - cell) (placed ?t - token) (on ?t - token ?c - cell)
               (has ?n - num) (succ ?a ?b - num))
  (:action move
    :parameters (?a ?b - cell)
    :precondition (and (at ?a) (next ?a ?b))
    :effect (and (not (at ?a)) (at ?b)))
  (:action place
    :parameters (?t - token ?c - cell ?n ?m - num)
    :precondition (and (at ?c) (not (placed ?t)) (has ?n) (succ ?m ?n)
                       (not (exists (?u - token) (on ?u ?c))))
    :effect (and (placed ?t) (on ?t ?c) (not (has ?n)) (has ?m)))
  (:action take
    :parameters (?t - token ?c - cell ?n ?m - num)
    :precondition (and (at ?c) (on ?t ?c) (has ?n) (succ ?n ?m))
    :effect (and (not (placed ?t)) (not (on ?t ?c)) (not (has ?n)) (has ?m))))
