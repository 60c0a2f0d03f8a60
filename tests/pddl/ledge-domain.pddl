; A row of columns the agent climbs (written for bcc's tests of the lifted search). The
; agent stands at a cell on a level (both change one step at a time); it walks onto a
; cell whose block one level below is solid, climbs one level onto a block in front,
; drops one level, puts a block it holds in front at its own level, takes a block in
; front back into its hands, and marks the cell in front at its own level.
(define (domain ledge)
  (:requirements :strips :typing :negative-preconditions)
  (:types agent cell level)
  (:predicates (at ?a - agent ?c - cell) (lvl ?a - agent ?l - level) (next ?c ?d - cell)
               (up ?l ?m - level) (solid ?c - cell ?l - level) (holding ?a - agent)
               (marked ?c - cell ?l - level))
  (:action walk
    :parameters (?a - agent ?c ?d - cell ?l ?b - level)
    :precondition (and (at ?a ?c) (lvl ?a ?l) (next ?c ?d) (up ?b ?l) (solid ?d ?b) (not (solid ?d ?l)))
    :effect (and (not (at ?a ?c)) (at ?a ?d)))
  (:action climb
    :parameters (?a - agent ?c ?d - cell ?l ?m - level)
    :precondition (and (at ?a ?c) (lvl ?a ?l) (next ?c ?d) (up ?l ?m) (solid ?d ?l) (not (solid ?d ?m)))
    :effect (and (not (at ?a ?c)) (at ?a ?d) (not (lvl ?a ?l)) (lvl ?a ?m)))
  (:action drop
    :parameters (?a - agent ?c ?d - cell ?l ?m ?b - level)
    :precondition (and (at ?a ?c) (lvl ?a ?m) (next ?c ?d) (up ?l ?m) (up ?b ?l) (solid ?d ?b)
                       (not (solid ?d ?l)) (not (solid ?d ?m)))
    :effect (and (not (at ?a ?c)) (at ?a ?d) (not (lvl ?a ?m)) (lvl ?a ?l)))
  (:action put
    :parameters (?a - agent ?c ?d - cell ?l - level)
    :precondition (and (at ?a ?c) (lvl ?a ?l) (next ?c ?d) (holding ?a) (not (solid ?d ?l)))
    :effect (and (solid ?d ?l) (not (holding ?a))))
  (:action take
    :parameters (?a - agent ?c ?d - cell ?l - level)
    :precondition (and (at ?a ?c) (lvl ?a ?l) (next ?c ?d) (not (holding ?a)) (solid ?d ?l))
    :effect (and (not (solid ?d ?l)) (holding ?a)))
  (:action mark
    :parameters (?a - agent ?c ?d - cell ?l - level)
    :precondition (and (at ?a ?c) (lvl ?a ?l) (next ?c ?d))
    :effect (marked ?d ?l)))
