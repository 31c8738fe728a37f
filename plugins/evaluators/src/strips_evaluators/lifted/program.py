"""The delete relaxation of a lifted PDDL task as a Datalog program, compiled once per task.

Every action becomes one rule per disjunct of its normalized precondition: the rule's body
is the disjunct's positive atoms, its heads the action's add effects, its cost the
action's. A conditional effect becomes a rule per (precondition disjunct, condition
disjunct) pair whose body joins both and whose heads are the effect's adds, at the
action's cost; a derived predicate (and an auxiliary one the normalizer makes for a
universal condition) a zero-cost rule; a goal that is not a conjunction of atoms the
zero-cost rules of the derived atom ``(@goal)``. This is exactly the relaxation the ground
heuristics use (:mod:`strips_evaluators.heuristics.relaxation`), read before grounding:
negative literals over fluent or derived predicates are ignored, negative static literals,
equalities and the parameters' types are checked, and nothing is enumerated up front but
the instances of rules whose body has no fluent atom (they hold in every state).

A rule is evaluated semi-naively by :mod:`.exploration`: when a fact is settled, every
rule with a body atom of its predicate is joined with that atom bound to the fact and the
other atoms bound to facts settled before (a :class:`Plan` per such *trigger* atom). A
binding is a list of *slots*, one per rule variable followed by the constants the rule
mentions, so every term is a slot number. Facts are the state's tuples
``(predicate, object, ...)``, so an argument's position in a fact is its position in the
atom plus one.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from operator import itemgetter

from strips_framework.errors import InputError
from strips_framework.grounding.normalize import Clause, Normalizer
from strips_framework.lifted.components import GroundAtom, static_predicates
from strips_framework.pddl.formulas import Atom, Parameter
from strips_framework.pddl.task import Action, PddlTask
from strips_framework.records import Record

#: The derived atom that stands for a goal which is not a conjunction of atoms (as in
#: grounding).
GOAL: GroundAtom = ("@goal",)
#: ``Rule.action`` of a rule that comes from a derived predicate or the goal.
AXIOM = -1
#: The most pairs of body atoms in different parts that may match one fact for which a
#: rule is still split (:meth:`Program._add_split`): each pair adds a rule with the two
#: atoms unified, and those rules' own pairs more, up to 2 ** pairs rules. On
#: organic-synthesis-MIT the splits pay up to 8 pairs (p17's Claisen condensation has
#: 7); an enolate alkylation with 41 makes a thousand rules, slower to explore than the
#: whole rule's joins.
MAX_SHARED_PAIRS = 8


class Check(Record):
    """A test on a binding, run as soon as its slots are bound: ``kind`` is ``"="``,
    ``"!="`` (two slots), ``"type"`` (slot ``a`` in ``domain``), ``"absent"`` or
    ``"present"`` (the static fact ``(predicate, *slots)`` does not hold, holds)."""

    kind: str
    slots: tuple[int, ...]
    predicate: str
    domain: frozenset[str]

    __slots__ = ("kind", "slots", "predicate", "domain")

    def __init__(
        self,
        kind: str,
        slots: tuple[int, ...],
        predicate: str = "",
        domain: frozenset[str] = frozenset(),
    ) -> None:
        self.kind = kind
        self.slots = slots
        self.predicate = predicate
        self.domain = domain


class Step(Record):
    """Match the facts of ``predicate`` whose arguments at ``positions`` are the values
    of the ``key`` slots (an index lookup); bind ``binds`` ``(position, slot)``, test
    that ``repeats`` ``(position, slot)`` equal slots bound in this same fact, then run
    ``checks``. ``fluent`` steps match facts settled in the state, the others static
    facts; ``before_trigger`` steps must not match the trigger fact itself (so a rule
    instance is found once, from its first atom that the new fact matches)."""

    predicate: str
    positions: tuple[int, ...]
    key: tuple[int, ...]
    binds: tuple[tuple[int, int], ...]
    repeats: tuple[tuple[int, int], ...]
    checks: tuple[Check, ...]
    fluent: bool
    before_trigger: bool

    __slots__ = (
        "predicate", "positions", "key", "binds", "repeats", "checks", "fluent",
        "before_trigger",
    )  # fmt: skip

    def __init__(
        self,
        predicate: str,
        positions: tuple[int, ...],
        key: tuple[int, ...],
        binds: tuple[tuple[int, int], ...],
        repeats: tuple[tuple[int, int], ...],
        checks: tuple[Check, ...],
        fluent: bool,
        before_trigger: bool,
    ) -> None:
        self.predicate = predicate
        self.positions = positions
        self.key = key
        self.binds = binds
        self.repeats = repeats
        self.checks = checks
        self.fluent = fluent
        self.before_trigger = before_trigger


class Plan(Record):
    """How to complete a binding of ``rule``: the ``trigger`` step (None for the plan
    that starts from nothing) binds the new fact, then ``steps`` join the other atoms,
    then the ``free`` slots no atom binds range over their ``domains`` (with
    ``final_checks``). ``probes[d]`` lists later fluent steps whose key is bound before
    step ``d``: if one of them has no fact under its key, no completion exists and step
    ``d``'s candidates are not enumerated (a semi-join filter: a relaxed exploration
    settles fluent facts gradually, and a static relation joined before an empty fluent
    one would be enumerated for nothing). ``heads_at`` is the number of steps after which
    every slot of the rule's heads is bound (``len(steps) + 1`` when a free slot is in a
    head): from there on a costed join knows what the completions would improve."""

    rule: Rule
    trigger: Step | None
    steps: tuple[Step, ...]
    free: tuple[int, ...]
    domains: tuple[tuple[str, ...], ...]
    final_checks: tuple[Check, ...]
    probes: tuple[tuple[int, ...], ...]
    heads_at: int

    __slots__ = (
        "rule", "trigger", "steps", "free", "domains", "final_checks", "probes", "heads_at",
    )  # fmt: skip

    def __init__(
        self,
        rule: Rule,
        trigger: Step | None,
        steps: tuple[Step, ...],
        free: tuple[int, ...],
        domains: tuple[tuple[str, ...], ...],
        final_checks: tuple[Check, ...],
        probes: tuple[tuple[int, ...], ...],
        heads_at: int,
    ) -> None:
        self.rule = rule
        self.trigger = trigger
        self.steps = steps
        self.free = free
        self.domains = domains
        self.final_checks = final_checks
        self.probes = probes
        self.heads_at = heads_at


class Rule(Record):
    """One relaxed rule. ``template`` is the initial slot list (``None`` for variables,
    then the constants); ``heads`` and ``negative`` are ``(predicate, slots)``;
    ``action`` indexes ``task.domain.actions`` (or is :data:`AXIOM`), ``arity`` is the
    number of the action's parameters (the first slots); the ground operator an instance
    belongs to is its action, ``operator`` (the precondition disjunct) and its first
    ``identity`` slots (the action's parameters and the disjunct's own variables). ``cost`` is the constant
    cost, or ``None`` when ``cost_term`` ``(function, slots)`` gives it per instance."""

    number: int
    template: tuple[str | None, ...]
    heads: tuple[tuple[str, tuple[int, ...]], ...]
    negative: tuple[tuple[str, tuple[int, ...]], ...]
    action: int
    arity: int
    operator: int
    identity: int
    cost: int | None
    cost_term: tuple[str, tuple[int, ...]]
    #: True when two body atoms share a predicate, so an instance may list a fact twice
    #: (the ground relaxation counts a precondition once).
    repeated_predicates: bool
    #: Per head, a function from the slot list to the ground head (an ``itemgetter``
    #: over the slots: the head's predicate name is a slot too).
    makers: tuple[Callable[[list], GroundAtom], ...]
    #: Per auxiliary body predicate (see :meth:`Program._add_split`), the pairs
    #: ``(part slot, rule slot)`` that carry the part's binding back into this rule's
    #: slots: the part binds the variables this rule does not join over.
    parts: dict[str, tuple[tuple[int, int], ...]]
    #: Pairs ``(slot, other)`` of a rule made by unifying two body atoms (see
    #: :meth:`Program._add_split`): the variable of ``slot`` was merged into the term of
    #: ``other``, so the joins leave it unbound and the relaxed plan copies it over.
    aliases: tuple[tuple[int, int], ...]

    __slots__ = (
        "number", "template", "heads", "negative", "action", "arity", "operator", "identity", "cost",
        "cost_term", "repeated_predicates", "makers", "parts", "aliases",
    )  # fmt: skip

    def __init__(
        self,
        number: int,
        template: tuple[str | None, ...],
        heads: tuple[tuple[str, tuple[int, ...]], ...],
        negative: tuple[tuple[str, tuple[int, ...]], ...],
        action: int,
        arity: int,
        operator: int,
        identity: int,
        cost: int | None,
        cost_term: tuple[str, tuple[int, ...]],
        repeated_predicates: bool,
        makers: tuple[Callable[[list], GroundAtom], ...],
        parts: dict[str, tuple[tuple[int, int], ...]] | None = None,
        aliases: tuple[tuple[int, int], ...] = (),
    ) -> None:
        self.number = number
        self.template = template
        self.heads = heads
        self.negative = negative
        self.action = action
        self.arity = arity
        self.operator = operator
        self.identity = identity
        self.cost = cost
        self.cost_term = cost_term
        self.repeated_predicates = repeated_predicates
        self.makers = makers
        self.parts = parts or {}
        self.aliases = aliases


class RuleProgram:
    """Relaxed rules over a set of objects and static facts, compiled to join plans; the
    front-ends say where the rules come from (:class:`Program` for a PDDL task)."""

    def __init__(
        self,
        static: frozenset[str],
        initial: Iterable[GroundAtom],
        objects_of: Callable[[tuple[str, ...]], tuple[str, ...]],
        source: str,
    ) -> None:
        self.static = static
        self.objects_of = objects_of
        #: The file named in messages about the rules.
        self.source = source
        self.derived: set[str] = set()
        self.objects = frozenset(objects_of(("object",)))
        #: Static facts by predicate, from the initial state.
        self.static_facts: dict[str, set[GroundAtom]] = {name: set() for name in static}
        #: The initial state's fluent facts by predicate (join-order estimates only).
        self.initial_facts: dict[str, list[GroundAtom]] = {}
        for fact in initial:
            if fact[0] in static:
                self.static_facts[fact[0]].add(fact)
            else:
                self.initial_facts.setdefault(fact[0], []).append(fact)
        self.numeric: dict[GroundAtom, int] = {}
        #: The names of the actions ``Rule.action`` indexes.
        self.action_names: list[str] = []
        self.rules: list[Rule] = []
        #: Per fluent (or derived) predicate, the plans it triggers.
        self.triggers: dict[str, list[Plan]] = {}
        #: Plans of rules without fluent body atoms: their instances hold in every state.
        self.unconditional: list[Plan] = []
        #: Plans that derive a derived predicate's facts from nothing (a full join), for
        #: the exact evaluation of derived predicates in a state (:mod:`.closure`).
        self.derivations: list[Plan] = []
        #: Index keys ``(predicate, positions)`` the plans look facts up with.
        self.fluent_indexes: dict[str, list[tuple[int, ...]]] = {}
        self.static_indexes: dict[tuple[str, tuple[int, ...]], dict[tuple[str, ...], list]] = {}
        #: The goal facts a state can change; explorations stop once all are settled.
        self.fluent_goal: tuple[GroundAtom, ...] = ()
        #: Goal facts of static predicates that do not hold: no state reaches the goal.
        self.static_goal_missing = 0
        #: The plans' compiled tests by plan identity (:func:`.matching.compiled`).
        self.compiled: dict[int, object] = {}

    def _index_static_facts(self) -> None:
        """Fills the static indexes the plans use (once every rule is added)."""
        for (predicate, positions), index in self.static_indexes.items():
            for fact in sorted(self.static_facts.get(predicate, ())):  # no order from hashing
                index.setdefault(tuple([fact[i] for i in positions]), []).append(fact)

    def cost_of(self, rule: Rule, slots: list[str]) -> int:
        """The cost of the instance of ``rule`` with these slot values."""
        if rule.cost is not None:
            return rule.cost
        function, arguments = rule.cost_term
        term = (function, *[slots[i] for i in arguments])
        value = self.numeric.get(term)
        if value is None:
            name = self.action_names[rule.action]
            raise InputError(
                self.source, None, None,
                f"no initial value for ({' '.join(term)}), the cost of {name!r}",
            )
        return value

    def _add(
        self,
        clause: Clause,
        params: tuple[Parameter, ...],
        heads: tuple[Atom, ...],
        action: int,
        operator: int,
        cost: int | Atom,
        line: int | None = None,
        identity: int | None = None,
        hidden: frozenset[str] = frozenset(),
        parts: dict[str, tuple[tuple[int, int], ...]] | None = None,
        derivation: bool = True,
        aliases: dict[str, str] | None = None,
    ) -> None:
        """A rule for ``clause`` (over ``params`` and its own variables) with these
        ``heads``, for ``action`` (or :data:`AXIOM`) at ``cost``: a number, or a numeric
        function term over the rule's variables (``line`` locates it in messages).
        ``hidden`` variables are bound by the auxiliary body atoms' ``parts``, not by this
        rule's joins; a rule that is not a ``derivation`` is left out of the exact
        evaluation of derived predicates. ``aliases`` maps variables merged into another
        term (:meth:`_unified`) to that term; they are hidden too."""
        everything = params + clause.params
        aliases = aliases or {}
        hidden = hidden | frozenset(aliases)
        slot = {param.name: i for i, param in enumerate(everything)}
        mentioned = [arg for atom in (*clause.positive, *clause.negative, *heads) for arg in atom.args]
        mentioned += aliases.values()
        if isinstance(cost, Atom):
            mentioned += cost.args
        for term in mentioned:
            if term not in slot:
                if term.startswith("?"):
                    raise InputError(self.source, line, None, f"variable {term} is not a parameter")
                slot[term] = len(slot)
        unique = dict.fromkeys(atom.predicate for atom in heads)
        names = {predicate: i for i, predicate in enumerate(unique, start=len(slot))}
        template = (None,) * len(everything) + tuple(list(slot)[len(everything):]) + tuple(names)
        body = [atom for atom in clause.positive if atom.predicate != "="]
        checks = [Check("=", (slot[a.args[0]], slot[a.args[1]]))
                  for a in clause.positive if a.predicate == "="]  # fmt: skip
        checks += [Check("!=", (slot[a.args[0]], slot[a.args[1]]))
                   for a in clause.negative if a.predicate == "="]  # fmt: skip
        checks += [
            Check("absent", tuple(slot[arg] for arg in a.args), a.predicate)
            for a in clause.negative
            if a.predicate in self.static
        ]
        for i, param in enumerate(everything):
            if param.name in hidden:
                continue
            domain = frozenset(self.objects_of(param.types))
            if domain != self.objects:
                checks.append(Check("type", (i,), domain=domain))
        cost_term: tuple[str, tuple[int, ...]] = ("", ())
        if isinstance(cost, Atom):
            cost_term = (cost.predicate, tuple(slot[a] for a in cost.args))
        predicates = [atom.predicate for atom in body]
        rule = Rule(
            number=len(self.rules),
            template=template,
            heads=tuple((a.predicate, tuple(slot[arg] for arg in a.args)) for a in heads),
            negative=tuple(
                (a.predicate, tuple(slot[arg] for arg in a.args))
                for a in clause.negative
                if a.predicate != "=" and a.predicate not in self.static
            ),
            action=action,
            arity=len(params) if action != AXIOM else 0,
            operator=operator,
            identity=len(everything) if identity is None else identity,
            cost=None if isinstance(cost, Atom) else cost,
            cost_term=cost_term,
            repeated_predicates=len(set(predicates)) < len(predicates),
            makers=tuple(
                _maker(a.predicate, names[a.predicate], tuple(slot[arg] for arg in a.args))
                for a in heads
            ),
            parts=parts,
            aliases=tuple((slot[name], slot[term]) for name, term in aliases.items()),
        )
        self.rules.append(rule)
        atoms = [(a.predicate, tuple(slot[arg] for arg in a.args)) for a in body]
        domains = {i: self.objects_of(p.types) for i, p in enumerate(everything)}
        # Hidden variables count as bound: the plans never enumerate them.
        variables = [i for i, p in enumerate(everything) if p.name not in hidden]
        if any(not domains[i] for i in variables):
            return  # a variable of a type without objects: the rule has no instance
        fluent = [i for i, (predicate, _) in enumerate(atoms) if predicate not in self.static]
        if action == AXIOM and derivation:
            self.derivations.append(self._plan(rule, atoms, None, checks, domains, variables))
        if not fluent:
            self.unconditional.append(self._plan(rule, atoms, None, checks, domains, variables))
        for position in fluent:
            plan = self._plan(rule, atoms, position, checks, domains, variables)
            self.triggers.setdefault(atoms[position][0], []).append(plan)

    def _plan(
        self,
        rule: Rule,
        atoms: list[tuple[str, tuple[int, ...]]],
        trigger: int | None,
        checks: list[Check],
        domains: dict[int, tuple[str, ...]],
        variables: list[int],
    ) -> Plan:
        """The join order: the trigger first, then greedily the atom with the fewest
        expected candidates: none for an atom whose arguments are all bound (a test),
        else the average bucket size of its index over the static facts for a static
        atom. Which facts of a fluent atom a state settles is not known up front: its
        bucket size lies between that over the initial state's facts and the product of
        its unbound variables' domain sizes (what exploration may reach), and their
        geometric mean is the estimate. Static atoms go first among equals: they filter
        without growing."""
        bound = set(range(len(domains), len(rule.template)))  # constants
        pending = list(checks)
        first = None
        if trigger is not None:
            first = self._step(atoms[trigger], bound, pending, fluent=True, before=False, trigger=True)
        rest = [i for i in range(len(atoms)) if i != trigger]
        steps: list[Step] = []
        bound_before: list[set[int]] = []
        while rest:
            def expected(i: int) -> tuple[float, bool]:
                predicate, terms = atoms[i]
                positions = tuple(p for p, t in enumerate(terms, start=1) if t in bound)
                if len(positions) == len(terms):
                    return 0, predicate not in self.static
                if predicate in self.static:
                    return self._bucket_size(predicate, positions), False
                reachable = 1.0
                for slot in {t for t in terms if t not in bound}:
                    reachable *= len(domains[slot])
                initial = max(self._bucket_size(predicate, positions), 1.0)
                return (initial * reachable) ** 0.5, True

            best = min(rest, key=expected)
            rest.remove(best)
            predicate, terms = atoms[best]
            is_fluent = predicate not in self.static
            previous = steps[-1] if steps else first
            if not is_fluent and previous is not None and all(t in bound for t in terms):
                # A static atom with every argument bound is a membership test, run with
                # the previous step's tests rather than as a join level of its own.
                previous.checks += (Check("present", terms, predicate),)
                continue
            before = trigger is not None and is_fluent and best < trigger
            bound_before.append(set(bound))
            steps.append(self._step(atoms[best], bound, pending, is_fluent, before))
        free = tuple(i for i in variables if i not in bound)
        probes: list[tuple[int, ...]] = []
        probed: set[int] = set()
        for depth, known in enumerate(bound_before):
            ready = [
                later
                for later in range(depth + 1, len(steps))
                if steps[later].fluent and later not in probed
                and all(slot in known for slot in steps[later].key)
            ]
            probed.update(ready)
            probes.append(tuple(ready))
        wanted = {slot for _, terms in rule.heads for slot in terms if slot < len(domains)}
        bound_before.append(bound)
        heads_at = next(
            (depth for depth, known in enumerate(bound_before) if wanted <= known),
            len(steps) + 1,
        )
        return Plan(
            rule=rule,
            trigger=first,
            steps=tuple(steps),
            free=free,
            domains=tuple(domains[i] for i in free),
            final_checks=tuple(pending),
            probes=tuple(probes),
            heads_at=heads_at,
        )

    def _bucket_size(self, predicate: str, positions: tuple[int, ...]) -> float:
        """The average number of static (or initial) facts of ``predicate`` per value of
        the arguments at ``positions``."""
        facts = self.static_facts.get(predicate) or self.initial_facts.get(predicate, ())
        keys = {tuple([fact[i] for i in positions]) for fact in facts}
        return len(facts) / max(len(keys), 1)

    def _step(
        self,
        atom: tuple[str, tuple[int, ...]],
        bound: set[int],
        pending: list[Check],
        fluent: bool,
        before: bool,
        trigger: bool = False,
    ) -> Step:
        predicate, terms = atom
        positions, key, binds, repeats = [], [], [], []
        newly: set[int] = set()
        for position, term in enumerate(terms, start=1):
            if term in bound and not trigger:
                positions.append(position)
                key.append(term)
            elif term in bound or term in newly:
                repeats.append((position, term))
            else:
                binds.append((position, term))
                newly.add(term)
        bound |= newly
        ready = [check for check in pending if all(s in bound for s in check.slots)]
        for check in ready:
            pending.remove(check)
        if not trigger:
            table = self.fluent_indexes if fluent else None
            if table is not None:
                table.setdefault(predicate, [])
                if tuple(positions) not in table[predicate]:
                    table[predicate].append(tuple(positions))
            else:
                self.static_indexes.setdefault((predicate, tuple(positions)), {})
        return Step(
            predicate=predicate,
            positions=tuple(positions),
            key=tuple(key),
            binds=tuple(binds),
            repeats=tuple(repeats),
            checks=tuple(ready),
            fluent=fluent,
            before_trigger=before,
        )

class Program(RuleProgram):
    """The relaxed program of a PDDL task (see the module docstring)."""

    def __init__(self, task: PddlTask) -> None:
        initial = [(atom.predicate, *atom.args) for atom in task.problem.init]
        super().__init__(static_predicates(task), initial, task.objects_of, task.problem_path)
        self.task = task
        self.action_names = [action.name for action in task.domain.actions]
        self.derived = {rule.head.predicate for rule in task.domain.derived}
        self.numeric = {
            (term.predicate, *term.args): value for term, value in task.problem.numeric
        }
        normalizer = Normalizer(task)
        for number, action in enumerate(task.domain.actions):
            for operator, clause in enumerate(normalizer.clauses(action.precondition)):
                cost = self._action_cost(action)
                self._add_split(clause, action.params, action.add, number, operator, cost, action.line)
                for effect in action.conditional:
                    if not effect.add:
                        continue
                    for condition in normalizer.clauses(effect.condition):
                        self._add_split(
                            clause.join(Clause(effect.params)).join(condition),
                            action.params,
                            effect.add,
                            number,
                            operator,
                            cost,
                            action.line,
                            identity=len(action.params) + len(clause.params),
                        )
        for derived in task.domain.derived:
            for clause in normalizer.clauses(derived.body):
                self._add(clause, derived.params, (derived.head,), AXIOM, 0, 0)
        goal_clauses = normalizer.clauses(task.problem.goal)
        self.goal: tuple[GroundAtom, ...]
        if len(goal_clauses) == 1 and not goal_clauses[0].params and not goal_clauses[0].negative:
            atoms = [atom for atom in goal_clauses[0].positive if atom.predicate != "="]
            self.goal = tuple(dict.fromkeys((atom.predicate, *atom.args) for atom in atoms))
        else:
            self.goal = (GOAL,)
            for clause in goal_clauses:
                self._add(clause, (), (Atom(GOAL[0], ()),), AXIOM, 0, 0)
        done = 0
        while done < len(normalizer.auxiliary):  # their bodies may add more
            auxiliary = normalizer.auxiliary[done]
            done += 1
            self.derived.add(auxiliary.head.predicate)
            for clause in normalizer.clauses(auxiliary.body):
                self._add(clause, auxiliary.params, (auxiliary.head,), AXIOM, 0, 0)
        self.derived.add(GOAL[0])
        self.static_goal_missing = sum(
            1
            for fact in self.goal
            if fact[0] in self.static and fact not in self.static_facts[fact[0]]
        )
        self.fluent_goal = tuple(fact for fact in self.goal if fact[0] not in self.static)
        self._index_static_facts()

    def _add_split(
        self,
        clause: Clause,
        params: tuple[Parameter, ...],
        heads: tuple[Atom, ...],
        action: int,
        operator: int,
        cost: int | Atom,
        line: int | None = None,
        identity: int | None = None,
        aliases: dict[str, str] | None = None,
        seen: set[tuple] | None = None,
    ) -> None:
        """An action's rule, split as lifted planners split Datalog rules when its body
        falls into parts that share no variable: each part becomes an auxiliary zero-cost
        rule whose head ``(@part-N-i ...)`` keeps only the part's variables the heads,
        the cost or a test across parts needs, and the rule joins those heads. Joining
        the parts separately costs the sum of their matches instead of the product, and
        a part's other variables are projected away.

        The auxiliary head's hadd (hmax) cost is the sum (maximum) of its part's body
        costs, so the rule's instance costs what the unsplit rule's would, as long as no
        fact can match atoms of two parts (the unsplit rule counts such a fact once):
        a rule with atoms of a fluent predicate in two parts that could match the same fact
        (no position that distinct constants, disjoint types or an inequality keeps
        apart) is kept whole. The relaxed plan rebuilds the full action instance from the parts'
        supporters (:func:`.exploration.expand`)."""
        everything = params + clause.params
        if self._without_instances(clause, everything):
            # Its parts would be explored for nothing: organic synthesis has actions over
            # halogens or chromium in tasks without such atoms, whose other parts (a
            # molecule each) reach tens of thousands of auxiliary atoms in a state.
            return
        kinds = {p.name: p for p in everything}
        parent = {name: name for name in kinds}

        def root(name: str) -> str:
            while parent[name] != name:
                name = parent[name]
            return name

        def union(names: Iterable[str]) -> None:
            names = [root(n) for n in names if n in kinds]
            for name in names[1:]:
                parent[name] = names[0]

        body = [a for a in clause.positive if a.predicate != "="]
        for atom in clause.positive:
            union(atom.args)
        unequal = {
            frozenset(a.args) for a in clause.negative if a.predicate == "=" and len(set(a.args)) == 2
        }

        def apart(first: Atom, second: Atom) -> bool:
            for x, y in zip(first.args, second.args):
                if x == y:
                    continue
                if frozenset((x, y)) in unequal:
                    return True
                domains = [
                    set(self.objects_of(kinds[t].types)) if t in kinds else {t} for t in (x, y)
                ]
                if not domains[0] & domains[1]:
                    return True
            return False

        aliases = aliases or {}
        overlapping = [
            (first, second)
            for i, first in enumerate(body)
            for second in body[i + 1:]
            if first.predicate == second.predicate and first.predicate not in self.static
            and {root(t) for t in first.args if t in kinds}
            != {root(t) for t in second.args if t in kinds}
            and not apart(first, second)
        ]  # fmt: skip
        variants = [self._unified(clause, heads, cost, kinds, pair) for pair in overlapping]
        if None in variants or len(variants) > MAX_SHARED_PAIRS:
            # The parts could share a fact, which the rule counts once, and the rules
            # for such instances cannot be written or would be too many: keep it whole
            # (joined as one part, they enumerate the product of their matches).
            self._add(clause, params, heads, action, operator, cost, line, identity, aliases=aliases)
            return
        # Split anyway: an instance whose parts share a fact costs the split rule that
        # fact twice, but it is also an instance of the rule with the two atoms unified,
        # which counts it once; the cheaper of the two is the unsplit rule's cost.
        seen = set() if seen is None else seen
        for variant in variants:
            if variant is False:
                continue  # the unified atoms need equal terms that must differ
            unified, unified_heads, unified_cost, merged = variant  # type: ignore[misc]
            key = (action, operator, identity, unified.positive, unified.negative)
            if key in seen:
                continue
            seen.add(key)
            composed = {name: merged.get(term, term) for name, term in aliases.items()}
            self._add_split(
                unified, params, unified_heads, action, operator, unified_cost, line, identity,
                aliases={**composed, **merged}, seen=seen,
            )  # fmt: skip
        groups: dict[str | None, list[Atom]] = {}
        for atom in body:
            variables = [t for t in atom.args if t in kinds]
            groups.setdefault(root(variables[0]) if variables else None, []).append(atom)
        if sum(1 for key in groups if key is not None) < 2 or not heads:
            # One part with variables (ground atoms match one fact each): nothing to gain.
            self._add(clause, params, heads, action, operator, cost, line, identity, aliases=aliases)
            return
        member = {name: root(name) for name in kinds}
        # The variables every head's rule needs: the cost's and those of tests across parts.
        shared = set(cost.args) if isinstance(cost, Atom) else set()
        kept_tests: list[tuple[bool, Atom]] = []
        part_tests: dict[str | None, list[tuple[bool, Atom]]] = {}
        for positive, atom in [(True, a) for a in clause.positive if a.predicate == "="] + [
            (False, a) for a in clause.negative
        ]:
            owners = {member[t] for t in atom.args if t in kinds}
            fluent = not positive and atom.predicate != "=" and atom.predicate not in self.static
            if not fluent and len(owners) == 1 and next(iter(owners)) in groups:
                part_tests.setdefault(next(iter(owners)), []).append((positive, atom))
            else:
                kept_tests.append((positive, atom))
                if not fluent:
                    shared.update(atom.args)
        needed = shared | {t for a in heads for t in a.args}
        slot = {p.name: i for i, p in enumerate(everything)}
        # Per part: its variables, the auxiliary atom over those some head needs.
        made: list[tuple[list[str], Atom]] = []
        for number, (key, atoms) in enumerate(groups.items()):
            variables = [v for v in kinds if key is not None and member[v] == key]
            kept = [v for v in variables if v in needed]
            own = part_tests.get(key, [])
            part = Clause(
                tuple(kinds[v] for v in variables if v not in needed),
                tuple(atoms) + tuple(a for positive, a in own if positive),
                tuple(a for positive, a in own if not positive),
            )
            head = Atom(f"@part-{len(self.rules)}-{number}", tuple(kept))
            self._add(part, tuple(kinds[v] for v in kept), (head,), AXIOM, 0, 0, derivation=False)
            made.append((variables, head))
        # A rule per set of heads that need the same variables, over the parts projected
        # to them (a ground operator achieves each of its adds at its own hadd cost).
        by_need: dict[tuple[tuple[str, ...], ...], list[Atom]] = {}
        for add in heads:
            wanted = shared | set(add.args)
            need = tuple(tuple(v for v in part.args if v in wanted) for _, part in made)
            by_need.setdefault(need, []).append(add)
        for number, (need, adds) in enumerate(by_need.items()):
            joined: list[Atom] = []
            parts: dict[str, tuple[tuple[int, int], ...]] = {}
            hidden: set[str] = set()
            for (variables, part), kept in zip(made, need):
                hidden.update(v for v in variables if v not in kept)
                rest = [v for v in variables if v not in kept]
                if len(kept) == len(part.args):
                    atom = part
                else:  # project the part further: @part-N-i-h(kept) :- @part-N-i(...)
                    atom = Atom(f"{part.predicate}-{number}", kept)
                    inner = [*part.args, *[v for v in variables if v not in part.args]]
                    order = list(kept) + rest
                    self._add(
                        Clause(tuple(kinds[v] for v in rest), (part,)),
                        tuple(kinds[v] for v in kept), (atom,), AXIOM, 0, 0, derivation=False,
                        hidden=frozenset(v for v in variables if v not in part.args),
                        parts={part.predicate: tuple((i, order.index(v)) for i, v in enumerate(inner))},
                    )  # fmt: skip
                inner = [*atom.args, *[v for v in variables if v not in atom.args]]
                parts[atom.predicate] = tuple((i, slot[v]) for i, v in enumerate(inner))
                joined.append(atom)
            main = Clause(
                clause.params,
                tuple(joined) + tuple(a for positive, a in kept_tests if positive),
                tuple(a for positive, a in kept_tests if not positive),
            )
            self._add(
                main, params, tuple(adds), action, operator, cost, line, identity,
                hidden=frozenset(hidden), parts=parts, aliases=aliases,
            )  # fmt: skip

    def _unified(
        self,
        clause: Clause,
        heads: tuple[Atom, ...],
        cost: int | Atom,
        kinds: dict[str, Parameter],
        pair: tuple[Atom, Atom],
    ) -> tuple[Clause, tuple[Atom, ...], int | Atom, dict[str, str]] | bool | None:
        """``clause`` (with its ``heads`` and ``cost``) with the two atoms of ``pair``
        made one: each variable merged into one term of its class (a constant, else the
        variable whose type is within every other's), and the map of the variables
        merged away; False when no instance exists (two constants, a type without the
        constant, an inequality between merged terms), None when the types of a class
        have no variable within all of them (the rule is then kept whole)."""
        first, second = pair
        classes: dict[str, set[str]] = {}
        for x, y in zip(first.args, second.args):
            merged = classes.get(x, {x}) | classes.get(y, {y})
            for term in merged:
                classes[term] = merged
        rename: dict[str, str] = {}
        for members in {id(m): m for m in classes.values()}.values():
            if len(members) < 2:
                continue
            constants = [t for t in members if t not in kinds]
            variables = [t for t in members if t in kinds]
            domains = {v: set(self.objects_of(kinds[v].types)) for v in variables}
            if constants:
                target = constants[0]
                if len(constants) > 1 or any(target not in d for d in domains.values()):
                    return False
            else:
                within = [v for v in variables if all(domains[v] <= d for d in domains.values())]
                if not within:
                    return None
                target = within[0]
            rename.update((v, target) for v in variables if v != target)

        def renamed(atom: Atom) -> Atom:
            return Atom(atom.predicate, tuple(rename.get(t, t) for t in atom.args))

        positive = tuple(dict.fromkeys(renamed(a) for a in clause.positive))
        negative = tuple(renamed(a) for a in clause.negative)
        if any(a.predicate == "=" and a.args[0] == a.args[1] for a in negative):
            return False
        unified = Clause(clause.params, positive, negative)
        unified_cost = renamed(cost) if isinstance(cost, Atom) else cost
        return unified, tuple(renamed(a) for a in heads), unified_cost, rename

    def _without_instances(self, clause: Clause, variables: tuple[Parameter, ...]) -> bool:
        """True when no state has an instance of a rule for ``clause``: a variable's type
        has no object, or a static predicate of its body has no fact."""
        if any(not self.objects_of(variable.types) for variable in variables):
            return True
        return any(
            atom.predicate in self.static and not self.static_facts[atom.predicate]
            for atom in clause.positive
        )

    def _action_cost(self, action: Action) -> int | Atom:
        """An action's cost as a rule takes it: 1 each without ``:action-costs``."""
        if not self.task.problem.minimize_cost:
            return 1
        return 0 if action.cost is None else action.cost

def _maker(name: str, name_slot: int, terms: tuple[int, ...]) -> Callable[[list], GroundAtom]:
    if not terms:
        atom = (name,)
        return lambda slots: atom
    return itemgetter(name_slot, *terms)
