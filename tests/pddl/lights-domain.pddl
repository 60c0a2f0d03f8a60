; Derived predicates (bcc inlines them): a room is lit when a lamp in it is on, dark when
; it is not lit, safe when lit or home; one walks only into safe rooms and switches the
; lamps of the next room. Written for bcc's tests.
(define (domain lights)
  (:requirements :typing :derived-predicates :negative-preconditions :existential-preconditions)
  (:types room lamp)
  (:predicates (at ?r - room) (adj ?a ?b - room) (in ?l - lamp ?r - room) (on ?l - lamp)
               (home ?r - room) (lit ?r - room) (dark ?r - room) (safe ?r - room)
               (another-on ?l - lamp))
  (:derived (lit ?r - room) (exists (?l - lamp) (and (in ?l ?r) (on ?l))))
  (:derived (dark ?r - room) (not (lit ?r)))
  (:derived (safe ?r - room) (lit ?r))
  (:derived (safe ?r - room) (home ?r))
  ; its quantified ?y must not capture the ?y of an action that uses it
  (:derived (another-on ?x - lamp) (exists (?y - lamp) (and (on ?y) (not (= ?x ?y)))))
  (:action move
    :parameters (?a ?b - room)
    :precondition (and (at ?a) (adj ?a ?b) (safe ?b))
    :effect (and (at ?b) (not (at ?a))))
  (:action switch-on
    :parameters (?a ?r - room ?y - lamp)
    :precondition (and (at ?a) (adj ?a ?r) (in ?y ?r) (dark ?r))
    :effect (on ?y))
  (:action switch-off
    :parameters (?a ?r - room ?y - lamp)
    :precondition (and (at ?a) (adj ?a ?r) (in ?y ?r) (on ?y) (another-on ?y))
    :effect (not (on ?y))))
