"""TPTP problems: read ``cnf``/``fof`` files, pose them to a prover, report an SZS status.

The reader is a hand-written recursive-descent parser over a small tokenizer: TPTP's
grammar for first-order formulas is tiny, and hand-written code gives exact error
positions ("expected ')'") without a grammar-debugging detour. Formulas become the core
AST of :mod:`strips_framework.logic.formulas`: TPTP variables are :class:`Var`, functors and
constants are strings and tuples, free variables of ``cnf`` clauses are wrapped in
:class:`Forall`.

Posing a problem (:meth:`TptpProblem.task`): conjectures are negated, and the negated
conjecture is the set of support; a ``question`` ``? [X, Y] : F`` becomes the STRIPS-style
goal ``F(x, y)`` with parameters ``x``, ``y`` (QA3, paper III.A), so the refutation's
parameter bindings are the answer. Without any goal role every formula is in the set of
support.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

from strips_framework.capabilities import ANSWER_LITERALS, declared
from strips_framework.errors import InputError
from strips_framework.logic.clauses import Clause
from strips_framework.logic.cnf import SkolemNames, clausify
from strips_framework.logic.formulas import (
    And,
    Atomic,
    Exists,
    Forall,
    Formula,
    Iff,
    Implies,
    Not,
    Or,
    Truth,
    Var,
    substitute_free,
)
from strips_framework.logic.parser import Token
from strips_framework.logic.terms import ANSWER, EQUALITY, SKOLEM_PREFIX, Param, Term
from strips_framework.records import Record
from strips_framework.user_files import MAX_NESTING, read_text
from strips_framework.worldmodel.proving import (
    GAVE_UP,
    PROVED,
    SATURATED,
    ProofResult,
    ProofTask,
    TheoremProver,
)

AXIOM_ROLES = frozenset(
    {"axiom", "hypothesis", "definition", "lemma", "theorem", "assumption", "plain", "unknown"}
)
GOAL_ROLES = frozenset({"conjecture", "negated_conjecture", "question"})

_TOKEN = re.compile(
    r"""
    (?P<space>\s+|%[^\n]*|/\*.*?\*/)
  | (?P<word>[a-z][A-Za-z0-9_]*)
  | (?P<var>[A-Z][A-Za-z0-9_]*)
  | (?P<dollar>\$\$?[a-z][A-Za-z0-9_]*)
  | (?P<quoted>'(?:[^'\\]|\\.)*')
  | (?P<distinct>"(?:[^"\\]|\\.)*")
  | (?P<number>[+-]?[0-9]+(?:[./][0-9]+)?(?:[eE][+-]?[0-9]+)?)
  | (?P<op><=>|<~>|=>|<=|~\||~&|!=|[()\[\],.:!?~&|=])
    """,
    re.VERBOSE | re.DOTALL,
)

_BINARY = {"=>", "<=", "<=>", "<~>", "~|", "~&"}
_T = TypeVar("_T")


class Inappropriate(InputError):
    """Input in a language the provers do not handle (SZS status ``Inappropriate``), as
    opposed to a syntax error: a defined symbol such as ``$sum``."""


def _tokenize(text: str, path: str) -> list[Token]:
    """The tokens of a TPTP text, of kinds "word", "var", "dollar", "quoted", "distinct",
    "number" and "op", then one of kind "end"."""
    tokens: list[Token] = []
    pos, line, line_start = 0, 1, 0
    while pos < len(text):
        found = _TOKEN.match(text, pos)
        if found is None:
            raise InputError(
                path, line, pos - line_start + 1, f"unexpected character {text[pos]!r}"
            )
        kind = found.lastgroup or ""
        if kind != "space":
            tokens.append(Token(kind, found.group(), line, pos - line_start + 1))
        newlines = found.group().count("\n")
        if newlines:
            line += newlines
            line_start = found.start() + found.group().rfind("\n") + 1
        pos = found.end()
    tokens.append(Token("end", "", line, pos - line_start + 1))
    return tokens


class TptpFormula(Record):
    """One annotated formula: ``language(name, role, formula)``."""

    name: str
    role: str
    language: str  # "cnf" or "fof"
    formula: Formula
    line: int

    __slots__ = ("name", "role", "language", "formula", "line")

    def __init__(self, name: str, role: str, language: str, formula: Formula, line: int) -> None:
        self.name = name
        self.role = role
        self.language = language
        self.formula = formula
        self.line = line


class _Parser:
    """Recursive descent over the tokens of one file."""

    def __init__(self, text: str, path: str) -> None:
        self.path = path
        self.tokens = _tokenize(text, path)
        self.pos = 0
        self.depth = 0  # parenthesized formulas, negations, quantifiers and terms being read
        #: Distinct objects (``"abc"``) and numbers met, in order: pairwise distinct.
        self.distinct: dict[str, None] = {}

    # -- token helpers --------------------------------------------------------------------

    def peek(self) -> Token:
        return self.tokens[self.pos]

    def next(self) -> Token:
        token = self.tokens[self.pos]
        self.pos += 1
        return token

    def error(self, expected: str, token: Token | None = None) -> InputError:
        token = token or self.peek()
        found = repr(token.text) if token.kind != "end" else "end of file"
        return InputError(
            self.path, token.line, token.column, f"expected {expected}, found {found}"
        )

    def uninterpreted(self, token: Token) -> Inappropriate:
        """A defined (``$sum``, ``$less``, ``$int``) or system (``$$...``) symbol: it has
        a meaning (arithmetic, types) that the provers do not interpret, and reading it as
        an uninterpreted symbol would make saturation claim Satisfiable of a problem
        whose arithmetic it ignored."""
        return Inappropriate(
            self.path,
            token.line,
            token.column,
            f"the defined symbol {token.text} is not supported (only $true and $false are "
            "interpreted; arithmetic and types are not)",
        )

    def expect(self, text: str) -> Token:
        token = self.peek()
        if token.kind != "op" or token.text != text:
            raise self.error(f"'{text}'")
        return self.next()

    def descend(self) -> None:
        """One level deeper (undone by ``self.depth -= 1``); input nested deeper than
        :data:`MAX_NESTING` is refused at the token that goes too deep."""
        self.depth += 1
        if self.depth > MAX_NESTING:
            token = self.peek()
            message = f"formula nested deeper than {MAX_NESTING} levels"
            raise InputError(self.path, token.line, token.column, message)

    def at(self, text: str) -> bool:
        token = self.peek()
        return token.kind == "op" and token.text == text

    # -- file level -------------------------------------------------------------------------

    def file(self) -> list[TptpFormula]:
        formulas: list[TptpFormula] = []
        while self.peek().kind != "end":
            token = self.next()
            if token.kind == "word" and token.text == "include":
                raise InputError(
                    self.path,
                    token.line,
                    token.column,
                    "include(...) is not supported: inline the included axioms",
                )
            if token.kind != "word" or token.text not in ("cnf", "fof"):
                raise self.error("cnf(...) or fof(...)", token)
            formulas.append(self.annotated(token))
        return formulas

    def annotated(self, start: Token) -> TptpFormula:
        self.expect("(")
        name = self.name("a formula name")
        self.expect(",")
        role_token = self.next()
        if role_token.kind != "word" or role_token.text not in AXIOM_ROLES | GOAL_ROLES:
            raise self.error("a formula role such as axiom or conjecture", role_token)
        self.expect(",")
        formula = self.formula()
        if start.text == "cnf" or role_token.text != "question":
            formula = _close(formula)
        if self.at(","):
            self.next()
            self.skip_annotations()
        self.expect(")")
        self.expect(".")
        return TptpFormula(name, role_token.text, start.text, formula, start.line)

    def name(self, what: str) -> str:
        token = self.next()
        if token.kind in ("word", "number"):
            return token.text
        if token.kind == "quoted":
            return _unquote(token.text)
        raise self.error(what, token)

    def skip_annotations(self) -> None:
        """Skip a source/useful-info annotation: balanced brackets up to the closing ')'."""
        depth = 0
        while True:
            token = self.peek()
            if token.kind == "end":
                raise self.error("')'")
            if token.kind == "op" and token.text in "([":
                depth += 1
            elif token.kind == "op" and token.text in ")]":
                if depth == 0:
                    return
                depth -= 1
            self.next()

    # -- formulas ---------------------------------------------------------------------------

    def formula(self) -> Formula:
        """A binary formula: ``&`` binds tighter than ``|``, both tighter than ``=>`` etc."""
        left = self.disjunction()
        token = self.peek()
        if token.kind == "op" and token.text in _BINARY:
            self.next()
            right = self.disjunction()
            return _binary(token.text, left, right)
        return left

    def disjunction(self) -> Formula:
        parts = [self.conjunction()]
        while self.at("|"):
            self.next()
            parts.append(self.conjunction())
        return parts[0] if len(parts) == 1 else Or(parts)

    def conjunction(self) -> Formula:
        parts = [self.unit()]
        while self.at("&"):
            self.next()
            parts.append(self.unit())
        return parts[0] if len(parts) == 1 else And(parts)

    def unit(self) -> Formula:
        token = self.peek()
        if token.kind != "op" or token.text not in ("(", "~", "!", "?"):
            return self.atomic()
        self.descend()
        self.next()
        if token.text == "(":
            inner = self.formula()
            self.expect(")")
        elif token.text == "~":
            inner = Not(self.unit())
        else:
            variables = self.variable_list()
            self.expect(":")
            body = self.unit()
            inner = Forall(variables, body) if token.text == "!" else Exists(variables, body)
        self.depth -= 1
        return inner

    def variable_list(self) -> list[Var]:
        return self.bracketed(self.variable)

    def bracketed(self, item: Callable[[], _T]) -> list[_T]:
        """``[item, item, ...]``: one or more."""
        self.expect("[")
        items = [item()]
        while self.at(","):
            self.next()
            items.append(item())
        self.expect("]")
        return items

    def variable(self) -> Var:
        token = self.next()
        if token.kind != "var":
            raise self.error("a variable (a capitalised name)", token)
        return Var(token.text)

    def atomic(self) -> Formula:
        token = self.peek()
        if token.kind == "dollar" and token.text in ("$true", "$false"):
            self.next()
            return Truth(token.text == "$true")
        if token.kind == "dollar":
            raise self.uninterpreted(token)
        if token.kind not in ("word", "quoted", "var", "distinct", "number", "dollar"):
            raise self.error("a formula")
        left = self.term()
        if self.at("=") or self.at("!="):
            negated = self.next().text == "!="
            equation = Atomic((EQUALITY, left, self.term()))
            return Not(equation) if negated else equation
        if token.kind in ("var", "distinct", "number"):
            raise self.error("'=' or '!=' after a term", self.peek())
        return Atomic(left if type(left) is tuple else (left,))

    def term(self) -> Term | Var:
        token = self.next()
        if token.kind == "var":
            return Var(token.text)
        if token.kind in ("distinct", "number"):
            self.distinct[token.text] = None
            return token.text
        if token.kind == "quoted":
            symbol = _unquote(token.text)
        elif token.kind == "word":
            symbol = token.text
        elif token.kind == "dollar":
            raise self.uninterpreted(token)
        else:
            raise self.error("a term", token)
        if not self.at("("):
            return symbol
        self.descend()
        self.next()
        args = [self.term()]
        while self.at(","):
            self.next()
            args.append(self.term())
        self.expect(")")
        self.depth -= 1
        return (symbol, *args)


def _unquote(text: str) -> str:
    """``'abc'`` is the symbol ``abc``; other quoted names keep their quotes to stay apart."""
    inner = re.sub(r"\\(.)", r"\1", text[1:-1])
    return inner if re.fullmatch(r"[a-z][A-Za-z0-9_]*", inner) else text


def _binary(op: str, left: Formula, right: Formula) -> Formula:
    if op == "=>":
        return Implies(left, right)
    if op == "<=":
        return Implies(right, left)
    if op == "<=>":
        return Iff(left, right)
    if op == "<~>":
        return Not(Iff(left, right))
    if op == "~|":
        return Not(Or((left, right)))
    return Not(And((left, right)))


def _free_variables(formula: Formula, bound: frozenset[Var], out: dict[Var, None]) -> None:
    def term(t: Term | Var) -> None:
        if isinstance(t, Var):
            if t not in bound:
                out[t] = None
        elif type(t) is tuple:
            for arg in t[1:]:
                term(arg)

    if isinstance(formula, Atomic):
        for arg in formula.atom[1:]:
            term(arg)
    elif isinstance(formula, Not):
        _free_variables(formula.body, bound, out)
    elif isinstance(formula, (And, Or)):
        for part in formula.parts:
            _free_variables(part, bound, out)
    elif isinstance(formula, Implies):
        _free_variables(formula.premise, bound, out)
        _free_variables(formula.conclusion, bound, out)
    elif isinstance(formula, Iff):
        _free_variables(formula.left, bound, out)
        _free_variables(formula.right, bound, out)
    elif isinstance(formula, (Forall, Exists)):
        _free_variables(formula.body, bound | frozenset(formula.variables), out)


def _close(formula: Formula) -> Formula:
    """Universally quantify the free variables (cnf clauses; stray free ones in fof)."""
    free: dict[Var, None] = {}
    _free_variables(formula, frozenset(), free)
    return Forall(tuple(free), formula) if free else formula


# -- problems ------------------------------------------------------------------------------


class TptpProblem(Record):
    """A parsed TPTP file."""

    path: str
    formulas: tuple[TptpFormula, ...]
    #: The distinct objects (``"abc"``) and numbers the formulas name. TPTP interprets
    #: them as themselves, so two different ones are unequal: :meth:`task` adds that as
    #: axioms, since without them saturation could claim Satisfiable of ``"a" = "b"``.
    #: (Arithmetic on numbers, ``$sum`` and the like, is refused when read.)
    distinct_objects: tuple[str, ...]

    __slots__ = ("path", "formulas", "distinct_objects")

    def __init__(
        self,
        path: str,
        formulas: tuple[TptpFormula, ...],
        distinct_objects: tuple[str, ...] = (),
    ) -> None:
        self.path = path
        self.formulas = formulas
        self.distinct_objects = distinct_objects

    @property
    def name(self) -> str:
        return Path(self.path).name.removesuffix(".p")

    @property
    def has_conjecture(self) -> bool:
        """Whether the status is about a conjecture (Theorem) rather than a clause set."""
        return any(f.role in ("conjecture", "question") for f in self.formulas)

    @property
    def question_variables(self) -> tuple[Param, ...]:
        """The parameters standing for a question's existential variables, in order."""
        params: list[Param] = []
        for f in self.formulas:
            if f.role == "question" and isinstance(f.formula, Exists):
                params.extend(Param(v.name) for v in f.formula.variables)
        return tuple(params)

    def task(
        self,
        effort: int = 1000,
        *,
        max_answers: int = 1,
        unique_names: bool = False,
        answers: bool = True,
        answer_literals: bool = False,
    ) -> ProofTask:
        """The proof task: negated goals are the set of support, the rest are axioms.

        Several conjectures are proved together (TPTP: their conjunction is the goal), so
        their conjunction is negated as one formula. ``answers`` false keeps a question's
        variables existential: the conjecture alone, without parameters to bind.
        ``answer_literals`` keeps them variables and records them in an answer literal
        instead (``? [X] : F(X)`` is negated as ``! [X] : (~F(X) | $answer(X))``, E's
        way), for a prover that declares ``answer-literals``.
        """
        skolem = SkolemNames()
        axioms: list[Clause] = []
        support: list[Clause] = []
        goals = [f for f in self.formulas if f.role in GOAL_ROLES]
        for f in self.formulas:
            if f.role == "negated_conjecture":
                support.extend(clausify(f.formula, label=f.name, skolem=skolem))
            elif f.role not in GOAL_ROLES:
                clauses = clausify(f.formula, label=f.name, skolem=skolem)
                (axioms if goals else support).extend(clauses)
        conjectures = [f for f in goals if f.role != "negated_conjecture"]
        if conjectures:
            goal = And(
                _answer_goal(f)
                if answer_literals
                else _goal_body(f)
                if answers
                else _close(f.formula)
                for f in conjectures
            )
            label = ",".join(f.name for f in conjectures)
            support.extend(clausify(Not(goal), label=label, skolem=skolem))
        objects = self.distinct_objects
        for i, first in enumerate(objects):
            for second in objects[i + 1 :]:
                unequal = Not(Atomic((EQUALITY, first, second)))
                clauses = clausify(unequal, label="$distinct", skolem=skolem)
                (axioms if goals else support).extend(clauses)
        return ProofTask(
            axioms, support, effort=effort, max_answers=max_answers, unique_names=unique_names
        )


def _goal_body(f: TptpFormula) -> Formula:
    """A conjecture as is; a question's outer existential variables become parameters."""
    if f.role != "question" or not isinstance(f.formula, Exists):
        return _close(f.formula)
    params = {v: Param(v.name) for v in f.formula.variables}
    return _close(substitute_free(f.formula.body, params))


def _answer_goal(f: TptpFormula) -> Formula:
    """A question ``? [X] : F(X)`` as ``? [X] : (F(X) & ~$answer(X))``, whose negation
    puts ``$answer(X)`` into every clause of the negated question; other goals as is."""
    if f.role != "question" or not isinstance(f.formula, Exists):
        return _close(f.formula)
    variables = tuple(f.formula.variables)
    answer = Not(Atomic((ANSWER, *variables)))
    return _close(Exists(variables, And((f.formula.body, answer))))


def parse_tptp(text: str, path: str = "<string>") -> TptpProblem:
    """Parse TPTP text; raise :class:`InputError` at the first token that does not fit."""
    parser = _Parser(text, path)
    formulas = tuple(parser.file())
    return TptpProblem(path, formulas, tuple(parser.distinct))


def load_tptp(path: str | Path) -> TptpProblem:
    """Read and parse a TPTP file; a missing or unreadable file is an :class:`InputError`."""
    return parse_tptp(read_text(Path(path)), str(path))


def szs_status(problem: TptpProblem, result: ProofResult) -> str:
    """The SZS status of ``result`` for ``problem``.

    With a conjecture: Theorem, CounterSatisfiable (saturated) or GaveUp; otherwise
    Unsatisfiable, Satisfiable or GaveUp. A question whose search saturated is GaveUp: its
    parameters may not be bound to Skolem terms or terms with variables (paper, III.A), so
    saturation shows only that no such answer exists, not that the conjecture is false.
    """
    if result.status == PROVED:
        return "Theorem" if problem.has_conjecture else "Unsatisfiable"
    if result.status == SATURATED and not problem.question_variables:
        return "CounterSatisfiable" if problem.has_conjecture else "Satisfiable"
    return GAVE_UP


#: How many times the given clauses of the conjecture's proof the search for a definite
#: answer gets, for a prover without answer literals (see :func:`prove_tptp`). The
#: answered questions of the TPTP dev set need up to 5 times (SYN031-1.q: 12 for the
#: proof, 58 for the answer); 8 leaves room.
ANSWER_SEARCH_FACTOR = 8


class TptpOutcome(Record):
    """What :func:`prove_tptp` found: the SZS status, the answer tuples (``None`` when
    there are none) and each proof attempt made, named (``problem``, ``question`` with
    answer literals, or ``conjecture`` then ``answer search`` with parameters)."""

    status: str
    answers: str | None
    attempts: tuple[tuple[str, ProofResult], ...]

    __slots__ = ("status", "answers", "attempts")

    def __init__(
        self,
        status: str,
        answers: str | None = None,
        attempts: tuple[tuple[str, ProofResult], ...] = (),
    ) -> None:
        self.status = status
        self.answers = answers
        self.attempts = attempts

    @property
    def effort_used(self) -> int:
        return sum(result.effort_used for _, result in self.attempts)


def prove_tptp(
    prover: TheoremProver,
    problem: TptpProblem,
    effort: int,
    settled: Callable[[TptpOutcome], None] | None = None,
) -> TptpOutcome:
    """``problem`` posed to ``prover``: its SZS status and answer tuples.

    A TPTP user asks whether the conjecture is a theorem, and for a question which
    instance. The conjecture goes first, a question's variables existential, on the
    whole ``effort``: that settles the status (``CounterSatisfiable`` or ``GaveUp`` also
    mean no answer will be found), and ``settled`` is told it before the answer is looked
    for (``strips prove`` reports it if the time runs out then). The answer search is
    then a second run:

    - a prover that declares ``answer-literals`` (:data:`ANSWER_LITERALS`) gets the
      question as E does: its variables stay variables, recorded in an answer literal,
      and the first refutation gives the answer, be it definite (``[[a]|_]``), a term
      with variables, a Skolem term (``[[esk1_0]|_]``) or a disjunction
      (``[([a]|[b])|_]``). A theorem always has one, so this run gets the whole
      ``effort`` again. (It comes second since answer literals slow a proof: clauses
      that differ only in their answers are not merged, and a clause with an answer
      literal cuts nothing as a unit: SYN074+1.q takes 482 given clauses with them
      against 57 without.)
    - any other prover is asked with the variables as parameters, which binds definite
      answers only (paper, III.A: the planner's way). Where none exists that search
      would spend its whole effort, so after a proof in ``u`` given clauses it gets
      :data:`ANSWER_SEARCH_FACTOR` times ``u`` (at most ``effort``).

    The planner binds parameters from definite answers only, never from answer literals.
    """
    if not problem.question_variables:
        result = prover.prove(problem.task(effort))
        status, answers = szs_status(problem, result), szs_answers(problem, result)
        return TptpOutcome(status, answers, (("problem", result),))
    plain = prover.prove(problem.task(effort, answers=False))
    if plain.status != PROVED:
        return TptpOutcome(_unproved(plain), None, (("conjecture", plain),))
    if settled is not None:
        settled(TptpOutcome("Theorem", None, (("conjecture", plain),)))
    if ANSWER_LITERALS in (declared(type(prover), "prover") or ()):
        result = prover.prove(problem.task(effort, answer_literals=True))
        answers = answer_tuples(result.proof[-1]) if result.proved and result.proof else None
    else:
        budget = min(effort, ANSWER_SEARCH_FACTOR * max(1, plain.effort_used))
        result = prover.prove(problem.task(budget))
        answers = szs_answers(problem, result) if result.proved else None
    return TptpOutcome("Theorem", answers, (("conjecture", plain), ("answer search", result)))


def _unproved(result: ProofResult) -> str:
    """The SZS status of a question not proved: saturated, its conjecture is false."""
    return "CounterSatisfiable" if result.status == SATURATED else GAVE_UP


def tptp_term(term: Term) -> str:
    """A term in TPTP syntax: clause variables as ``X0``, ``X1``..., Skolem symbols
    ``sk!3`` as E names its own, ``esk3_0`` (the number, then the arity)."""
    if type(term) is int:
        return f"X{term}"
    if type(term) is tuple:
        functor = _tptp_symbol(term[0], len(term) - 1)
        return f"{functor}({','.join(tptp_term(a) for a in term[1:])})"
    return _tptp_symbol(str(term), 0)


def _tptp_symbol(symbol: str, arity: int) -> str:
    if symbol.startswith(SKOLEM_PREFIX):
        return f"esk{symbol[len(SKOLEM_PREFIX):]}_{arity}"
    return symbol


def answer_tuples(clause: Clause) -> str | None:
    """The SZS answer of a refutation ending in answer literals: ``[[a, b]|_]`` for one,
    ``[([a]|[b])|_]`` for a disjunction (E's notation); ``None`` for the empty clause."""
    tuples = [
        f"[{', '.join(tptp_term(arg) for arg in atom[1:])}]"
        for positive, atom in clause.literals
        if positive and atom[0] == ANSWER
    ]
    if not tuples:
        return None
    if len(tuples) == 1:
        return f"[{tuples[0]}|_]"
    return f"[({'|'.join(tuples)})|_]"


def szs_answers(problem: TptpProblem, result: ProofResult) -> str | None:
    """``[[a, b], ...|_]``: one tuple per answer, ``_`` for a variable the proof left free."""
    params = problem.question_variables
    if not params or not result.answers:
        return None
    tuples = []
    for answer in result.answers:
        bound = dict(answer)
        values = [tptp_term(bound[p]) if p in bound else "_" for p in params]
        tuples.append(f"[{', '.join(values)}]")
    return f"[{', '.join(tuples)}|_]"


def parse_answers(text: str) -> list[tuple[Term | Var, ...]]:
    """The tuples of an SZS answer, ``[[a, f(X1)]|_]`` or ``[([a]|[b])|_]`` (E's
    notation, and ours): one tuple for a definite answer, several for a disjunction.
    Variables are :class:`Var`; symbols are as written (``esk1_0`` stays a name)."""
    text = text.strip()
    if not text.endswith("|_]"):
        raise InputError("<answer>", 1, len(text), "expected an answer ending in '|_]'")
    parser = _Parser(text[:-3], "<answer>")
    parser.expect("[")
    disjunctive = parser.at("(")
    if disjunctive:
        parser.next()
    tuples = [_answer_tuple(parser)]
    while disjunctive and parser.at("|"):
        parser.next()
        tuples.append(_answer_tuple(parser))
    if disjunctive:
        parser.expect(")")
    if parser.peek().kind != "end":
        raise parser.error("'|_]'")
    return tuples


def _answer_tuple(parser: _Parser) -> tuple[Term | Var, ...]:
    return tuple(parser.bracketed(parser.term))


def formula_to_tptp(formula: Formula) -> str:
    """``formula`` in TPTP's ``fof`` syntax (fully parenthesized), for handing a problem
    built from a parsed one to another prover (checking an answer with E)."""
    if isinstance(formula, Truth):
        return "$true" if formula.value else "$false"
    if isinstance(formula, Atomic):
        atom = formula.atom
        if atom[0] == EQUALITY and len(atom) == 3:
            return f"({_fof_term(atom[1])} = {_fof_term(atom[2])})"
        return _fof_term(atom if len(atom) > 1 else atom[0])
    if isinstance(formula, Not):
        return f"~ {formula_to_tptp(formula.body)}"
    if isinstance(formula, (And, Or)):
        if not formula.parts:
            return "$true" if isinstance(formula, And) else "$false"
        op = " & " if isinstance(formula, And) else " | "
        return "(" + op.join(formula_to_tptp(part) for part in formula.parts) + ")"
    if isinstance(formula, Implies):
        return f"({formula_to_tptp(formula.premise)} => {formula_to_tptp(formula.conclusion)})"
    if isinstance(formula, Iff):
        return f"({formula_to_tptp(formula.left)} <=> {formula_to_tptp(formula.right)})"
    if isinstance(formula, (Forall, Exists)):
        quantifier = "!" if isinstance(formula, Forall) else "?"
        names = ", ".join(v.name for v in formula.variables)
        return f"({quantifier} [{names}] : {formula_to_tptp(formula.body)})"
    raise TypeError(f"not a formula: {formula!r}")


def _fof_term(term: Term | Var) -> str:
    if isinstance(term, Var):
        return term.name
    if type(term) is tuple:
        return f"{term[0]}({','.join(_fof_term(arg) for arg in term[1:])})"
    return str(term)


def szs_report(problem: TptpProblem, result: ProofResult) -> str:
    """The lines a TPTP prover prints: the status and, for questions, the answers."""
    return szs_lines(problem, szs_status(problem, result), szs_answers(problem, result))


def szs_lines(problem: TptpProblem, status: str, answers: str | None) -> str:
    """``% SZS status ...`` and, with answers, ``% SZS answers Tuple ...``."""
    lines = [f"% SZS status {status} for {problem.name}"]
    if answers is not None:
        lines.append(f"% SZS answers Tuple {answers} for {problem.name}")
    return "\n".join(lines)
