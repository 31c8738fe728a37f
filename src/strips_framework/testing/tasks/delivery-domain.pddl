; A truck delivers parcels over roads of different lengths (action costs): the plan with
; the fewest steps is not the cheapest one.
(define (domain delivery)
  (:requirements :strips :typing :action-costs)
  (:types city parcel)
  (:predicates (road ?a ?b - city) (truck-at ?c - city) (at ?p - parcel ?c - city)
               (in ?p - parcel))
  (:functions (total-cost) - number (length ?a ?b - city) - number)
  (:action drive
    :parameters (?from ?to - city)
    :precondition (and (truck-at ?from) (road ?from ?to))
    :effect (and (not (truck-at ?from)) (truck-at ?to)
                 (increase (total-cost) (length ?from ?to))))
  (:action load
    :parameters (?p - parcel ?c - city)
    :precondition (and (truck-at ?c) (at ?p ?c))
    :effect (and (in ?p) (not (at ?p ?c)) (increase (total-cost) 1)))
  (:action unload
    :parameters (?p - parcel ?c - city)
    :precondition (and (truck-at ?c) (in ?p))
    :effect (and (at ?p ?c) (not (in ?p)) (increase (total-cost) 1))))
