; A robot moves between rooms along one-way doors; the cost of a move is its length.
(define (domain corridors)
  (:requirements :strips :typing :action-costs)
  (:types room)
  (:predicates (at ?r - room) (door ?from - room ?to - room))
  (:functions (total-cost) - number (length ?from - room ?to - room) - number)
  (:action move
    :parameters (?from - room ?to - room)
    :precondition (and (at ?from) (door ?from ?to))
    :effect (and (not (at ?from)) (at ?to) (increase (total-cost) (length ?from ?to)))))
