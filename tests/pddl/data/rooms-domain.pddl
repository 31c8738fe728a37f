; A hand-written ADL domain exercising every supported feature at once: a type hierarchy,
; either-types, constants, equality, negative preconditions, or/imply/exists/forall,
; a recursive derived predicate, and action costs from numbers and from a function.
(define (domain rooms)
  (:requirements :strips :typing :adl :derived-predicates :action-costs :equality
                 :negative-preconditions :universal-preconditions :existential-preconditions
                 :disjunctive-preconditions)
  (:types place key - object
          room hall - place)
  (:constants master - key)
  (:predicates (at ?p - place) (door ?a ?b - place) (locked ?a ?b - place)
               (has ?k - key) (key-at ?k - key ?p - place) (fits ?k - key ?a ?b - place)
               (visited ?p - place) (reachable ?p - place) (cleaned ?r - room))
  (:functions (total-cost) - number (length ?a ?b - place) - number)

  (:derived (reachable ?p - place)
    (or (at ?p)
        (exists (?q - place) (and (reachable ?q) (door ?q ?p) (not (locked ?q ?p))))))

  (:action move
    :parameters (?from ?to - place)
    :precondition (and (at ?from) (not (= ?from ?to)) (door ?from ?to) (not (locked ?from ?to)))
    :effect (and (not (at ?from)) (at ?to) (visited ?to)
                 (increase (total-cost) (length ?from ?to))))

  (:action pick
    :parameters (?k - key ?p - place)
    :precondition (and (at ?p) (key-at ?k ?p))
    :effect (and (has ?k) (not (key-at ?k ?p)) (increase (total-cost) 1)))

  (:action drop
    :parameters (?k - key ?p - (either room hall))
    :precondition (and (at ?p) (has ?k))
    :effect (and (not (has ?k)) (key-at ?k ?p)))

  (:action unlock
    :parameters (?a ?b - place ?k - key)
    :precondition (and (at ?a) (locked ?a ?b)
                       (or (has master) (and (has ?k) (fits ?k ?a ?b))))
    :effect (and (not (locked ?a ?b)) (not (locked ?b ?a)) (increase (total-cost) 2)))

  (:action clean
    :parameters (?r - room)
    :precondition (and (at ?r)
                       (imply (visited ?r) (forall (?k - key) (not (key-at ?k ?r)))))
    :effect (cleaned ?r)))
