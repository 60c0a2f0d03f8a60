; Heaps dug up and spent on building (written for bcc's tests of the lifted search). The
; agent walks a row of cells; `dig` on a heap's cell takes the heap and steps its count
; up; `build` on a cell not yet built steps the count down. Every `build` spends one step
; of the count (a supply, heuristics/lifted_supplies.py) and `dig` refills it.
(define (domain stock)
  (:requirements :strips :typing :negative-preconditions)
  (:types agent cell num)
  (:predicates (at ?a - agent ?c - cell) (next ?c ?d - cell) (has ?a - agent ?n - num)
               (succ ?n ?m - num) (heap ?c - cell) (built ?c - cell))
  (:action move
    :parameters (?a - agent ?c ?d - cell)
    :precondition (and (at ?a ?c) (next ?c ?d))
    :effect (and (not (at ?a ?c)) (at ?a ?d)))
  (:action dig
    :parameters (?a - agent ?c - cell ?n ?m - num)
    :precondition (and (at ?a ?c) (heap ?c) (has ?a ?n) (succ ?n ?m))
    :effect (and (not (heap ?c)) (not (has ?a ?n)) (has ?a ?m)))
  (:action build
    :parameters (?a - agent ?c - cell ?n ?m - num)
    :precondition (and (at ?a ?c) (not (built ?c)) (has ?a ?n) (succ ?m ?n))
    :effect (and (built ?c) (not (has ?a ?n)) (has ?a ?m))))
