"""OpenSCENARIO 1.x expressions: ``${...}`` in attribute values.

Grammar (ASAM OpenSCENARIO 1.2, section "Expressions"): numbers, ``$parameter`` references, ``+ - * /
%``, unary minus, parentheses, the functions round, floor, ceil, sqrt, pow, sin, cos, tan, asin, acos,
atan, sign, abs, max, min, and the boolean operators ``not``, ``and``, ``or`` on 0/1 values. A
recursive-descent parser; nothing is passed to Python's ``eval``.
"""

from __future__ import annotations

import math
import re

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
    toks = _tokens(expression)
    pos = 0

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

    def number(value: object, name: str) -> float:
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

    def disjunction() -> float:
        left = conjunction()
        while peek() == ("name", "or"):
            take()
            right = conjunction()
            left = 1.0 if (left != 0 or right != 0) else 0.0
        return left

    def conjunction() -> float:
        left = negation()
        while peek() == ("name", "and"):
            take()
            right = negation()
            left = 1.0 if (left != 0 and right != 0) else 0.0
        return left

    def negation() -> float:
        if peek() == ("name", "not"):
            take()
            return 0.0 if negation() != 0 else 1.0
        return additive()

    def additive() -> float:
        left = multiplicative()
        while peek() in (("op", "+"), ("op", "-")):
            op = take()[1]
            right = multiplicative()
            left = left + right if op == "+" else left - right
        return left

    def multiplicative() -> float:
        left = unary()
        while peek() in (("op", "*"), ("op", "/"), ("op", "%")):
            op = take()[1]
            right = unary()
            if op == "*":
                left *= right
            elif right == 0:
                raise ExpressionError("division by zero")
            else:
                left = left / right if op == "/" else math.fmod(left, right)
        return left

    def unary() -> float:
        if peek() == ("op", "-"):
            take()
            return -unary()
        if peek() == ("op", "+"):
            take()
            return unary()
        return primary()

    def primary() -> float:
        tok = take()
        kind, text = tok
        if kind == "num":
            return float(text)
        if kind == "param":
            name = text[1:]
            if name not in parameters:
                raise ExpressionError(f"parameter ${name} is not declared")
            return number(parameters[name], name)
        if kind == "op" and text == "(":
            value = disjunction()
            take(")")
            return value
        if kind == "name" and text in _FUNCTIONS:
            arity, fn = _FUNCTIONS[text]
            take("(")
            args = [disjunction()]
            while peek() == ("op", ","):
                take()
                args.append(disjunction())
            take(")")
            if len(args) != arity:
                raise ExpressionError(f"{text}() takes {arity} argument(s), got {len(args)}")
            try:
                return float(fn(*args))
            except (ValueError, OverflowError) as exc:
                raise ExpressionError(f"{text}{tuple(args)}: {exc}") from None
        raise ExpressionError(f"unexpected {text!r}")

    value = disjunction()
    if pos != len(toks):
        raise ExpressionError(f"unexpected {toks[pos][1]!r}")
    return value
