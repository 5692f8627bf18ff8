"""OpenSCENARIO 1.x expressions: ``${...}`` in attribute values.

Grammar (ASAM OpenSCENARIO 1.2, section "Expressions"): numbers, ``$parameter`` references, ``+ - * /
%``, unary minus, parentheses, the functions round, floor, ceil, sqrt, pow, sin, cos, tan, asin, acos,
atan, sign, abs, max, min, and the boolean operators ``not``, ``and``, ``or`` on 0/1 values. A
recursive-descent parser; nothing is passed to Python's ``eval``.
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Callable

_TOKEN = re.compile(
    r"\s*(?:(?P<num>\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)|(?P<param>\$[A-Za-z_][A-Za-z0-9_]*)"
    r"|(?P<name>[A-Za-z_][A-Za-z0-9_]*)|(?P<op>[-+*/%(),]))"
)

_FUNCTIONS = {
    "round": (1, lambda a: float(math.floor(a + 0.5)) if a >= 0 else -float(math.floor(-a + 0.5))),
    "floor": (1, lambda a: float(math.floor(a))),
    "ceil": (1, lambda a: float(math.ceil(a))),
    "sqrt": (1, math.sqrt),
    "pow": (2, math.pow),
    "sin": (1, math.sin),
    "cos": (1, math.cos),
    "tan": (1, math.tan),
    "asin": (1, math.asin),
    "acos": (1, math.acos),
    "atan": (1, math.atan),
    "sign": (1, lambda a: float((a > 0) - (a < 0))),
    "abs": (1, abs),
    "max": (2, max),
    "min": (2, min),
}


class ExpressionError(ValueError):
    pass


#: Bounds that keep a hostile expression from exhausting the stack or the time (an expression in an
#: attribute is a formula, not a program): tokens in one expression, and nesting of parentheses,
#: calls and unary operators.
MAX_TOKENS = 2000
MAX_DEPTH = 64
#: Named constants (esmini accepts ``pi``; the standard's grammar has none, so vei follows esmini).
CONSTANTS = {"pi": math.pi}


def _tokens(text: str) -> list[tuple[str, str]]:
    out, pos = [], 0
    text = text.rstrip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            raise ExpressionError(f"unexpected character {text[pos:].strip()[:1]!r} at position {pos + 1}")
        kind = m.lastgroup
        out.append((kind, m.group(kind)))
        pos = m.end()
    return out


def evaluate(expression: str, parameters: dict[str, object]) -> float:
    """Value of ``expression`` (the text inside ``${...}``); parameters by name without ``$``."""
    return compile_expression(expression)(parameters)


def _number(value: object, name: str) -> float:
    if isinstance(value, bool):
        return 1.0 if value else 0.0
    if isinstance(value, str):
        if value in ("true", "false"):
            return 1.0 if value == "true" else 0.0
        try:
            return float(value)
        except ValueError:
            raise ExpressionError(f"parameter ${name} = {value!r} is not a number") from None
    return float(value)


Compiled = Callable[[dict[str, object]], float]


@functools.lru_cache(maxsize=1024)
def compile_expression(expression: str) -> Compiled:
    """``expression`` parsed once into a function of the parameters: a sweep evaluates the same few
    expressions for every variant. Syntax errors raise here, value errors (an undeclared or non-numeric
    parameter, division by zero, a function outside its domain) when the function is called."""
    if len(expression) > 20 * MAX_TOKENS:
        raise ExpressionError(f"longer than {20 * MAX_TOKENS} characters")
    toks = _tokens(expression)
    if len(toks) > MAX_TOKENS:
        raise ExpressionError(f"{len(toks)} tokens; at most {MAX_TOKENS}")
    pos = 0
    depth = 0

    def deeper() -> None:
        nonlocal depth
        depth += 1
        if depth > MAX_DEPTH:
            raise ExpressionError(f"nested deeper than {MAX_DEPTH} levels")

    def peek() -> tuple[str, str] | None:
        return toks[pos] if pos < len(toks) else None

    def take(expected: str | None = None) -> tuple[str, str]:
        nonlocal pos
        tok = peek()
        if tok is None or (expected is not None and tok[1] != expected):
            raise ExpressionError(
                f"expected {expected or 'a value'} at the end"
                if tok is None
                else f"expected {expected!r}, found {tok[1]!r}"
            )
        pos += 1
        return tok

    def boolean_chain(word: str, operand: Callable[[], Compiled], combine) -> Compiled:
        """``a word b word c ...`` (or/and): every operand evaluated, in a loop."""
        parts = [operand()]
        while peek() == ("name", word):
            take()
            parts.append(operand())
        if len(parts) == 1:
            return parts[0]
        return lambda p: 1.0 if combine([f(p) != 0 for f in parts]) else 0.0

    def disjunction() -> Compiled:
        return boolean_chain("or", conjunction, any)

    def conjunction() -> Compiled:
        return boolean_chain("and", negation, all)

    def negation() -> Compiled:
        if peek() == ("name", "not"):
            take()
            deeper()
            a = negation()
            return lambda p: 0.0 if a(p) != 0 else 1.0
        return additive()

    def additive() -> Compiled:
        # a chain is evaluated in a loop, left to right: no call depth that grows with its length
        first = multiplicative()
        rest: list[tuple[str, Compiled]] = []
        while peek() in (("op", "+"), ("op", "-")):
            op = take()[1]
            rest.append((op, multiplicative()))
        if not rest:
            return first

        def chain(p: dict[str, object]) -> float:
            value = first(p)
            for op, f in rest:
                value = value + f(p) if op == "+" else value - f(p)
            return value

        return chain

    def multiplicative() -> Compiled:
        first = unary()
        rest: list[tuple[str, Compiled]] = []
        while peek() in (("op", "*"), ("op", "/"), ("op", "%")):
            op = take()[1]
            rest.append((op, unary()))
        if not rest:
            return first

        def chain(p: dict[str, object]) -> float:
            value = first(p)
            for op, f in rest:
                right = f(p)
                if op == "*":
                    value = value * right
                elif right == 0:
                    raise ExpressionError("division by zero")
                elif op == "/":
                    value = value / right
                elif not math.isfinite(value):  # (a product that overflowed: fmod has no remainder of it)
                    raise ExpressionError(f"{value} % {right} has no remainder")
                else:
                    value = math.fmod(value, right)
            return value

        return chain

    def unary() -> Compiled:
        if peek() == ("op", "-"):
            take()
            deeper()
            a = unary()
            return lambda p: -a(p)
        if peek() == ("op", "+"):
            take()
            deeper()
            return unary()
        return primary()

    def parameter(name: str) -> Compiled:
        def f(p: dict[str, object]) -> float:
            if name not in p:
                raise ExpressionError(f"parameter ${name} is not declared")
            return _number(p[name], name)

        return f

    def call(name: str, fn, args: list[Compiled]) -> Compiled:
        def f(p: dict[str, object]) -> float:
            values = [a(p) for a in args]
            try:
                return float(fn(*values))
            except (ValueError, OverflowError) as exc:
                raise ExpressionError(f"{name}{tuple(values)}: {exc}") from None

        return f

    def primary() -> Compiled:
        kind, text = take()
        if kind == "num":
            value = float(text)
            if not math.isfinite(value):  # (1e400: beyond a double, as no parameter value may be)
                raise ExpressionError(f"number {text} is out of range")
            return lambda p: value
        if kind == "param":
            return parameter(text[1:])
        if kind == "op" and text == "(":
            nonlocal depth
            deeper()
            inner = disjunction()
            take(")")
            depth -= 1
            return inner
        if kind == "name" and text in CONSTANTS:
            value = CONSTANTS[text]
            return lambda p: value
        if kind == "name" and text in _FUNCTIONS:
            arity, fn = _FUNCTIONS[text]
            deeper()
            take("(")
            args = [disjunction()]
            while peek() == ("op", ","):
                take()
                args.append(disjunction())
            take(")")
            if len(args) != arity:
                raise ExpressionError(f"{text}() takes {arity} argument(s), got {len(args)}")
            depth -= 1
            return call(text, fn, args)
        raise ExpressionError(f"unexpected {text!r}")

    compiled = disjunction()
    if pos != len(toks):
        raise ExpressionError(f"unexpected {toks[pos][1]!r}")
    return compiled
