"""Safe arithmetic for scene parameters: ``"0.7 * rocker"``, ``"sqrt(2) * 0.1"``."""
from __future__ import annotations

import ast
import math
import operator

from graphplan.util.errors import SceneError, keyed_error

_BINARY = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
           ast.Div: operator.truediv, ast.Pow: operator.pow}
_UNARY = {ast.UAdd: operator.pos, ast.USub: operator.neg}
_FUNCS = {"sqrt": math.sqrt, "sin": math.sin, "cos": math.cos, "tan": math.tan,
          "asin": math.asin, "acos": math.acos, "atan": math.atan, "radians": math.radians,
          "degrees": math.degrees, "abs": abs}
_CONSTS = {"pi": math.pi}


def evaluate(text: str, names: dict[str, float], where: str) -> float:
    """Evaluate an arithmetic expression over numbers, known names and a few functions."""
    from graphplan.model.bounds import MAX_EXPRESSION, MAX_EXPRESSION_DEPTH, short
    shown = repr(short(text))
    if len(text) > MAX_EXPRESSION:
        raise keyed_error(SceneError, where, "", "ex long", text=shown, most=MAX_EXPRESSION)
    try:
        source = text.strip()
        tree = ast.parse(source, mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        raise keyed_error(SceneError, where, "", "ex unreadable", text=shown) from None
    if _depth(tree) > MAX_EXPRESSION_DEPTH:
        raise keyed_error(SceneError, where, "", "ex deep", text=shown, most=MAX_EXPRESSION_DEPTH)
    text = short(text)

    def walk(node: ast.AST) -> float:
        if isinstance(node, ast.Expression):
            return walk(node.body)
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) \
                and not isinstance(node.value, bool):
            if "_" in (ast.get_source_segment(source, node) or ""):   # 7_2 is not 72 to a person
                raise keyed_error(SceneError, where, "", "ex underscore", text=repr(text))
            return float(node.value)
        if isinstance(node, ast.Name):
            if node.id in names:
                return float(names[node.id])
            if node.id in _CONSTS:
                return _CONSTS[node.id]
            if node.id == text.strip():          # a word where a number is wanted ("horizontal")
                raise keyed_error(SceneError, where, "", "ex bare word", name=repr(node.id), params="[params]",
                                  known=", ".join(sorted(names)) or "—")
            raise keyed_error(SceneError, where, "", "ex unknown name", name=repr(node.id), text=repr(text))
        if isinstance(node, ast.BinOp) and type(node.op) in _BINARY:
            result = _BINARY[type(node.op)](walk(node.left), walk(node.right))
            if isinstance(result, complex):            # (-8) ** 0.5
                raise ValueError("the result is not a real number")
            return float(result)
        if isinstance(node, ast.UnaryOp) and type(node.op) in _UNARY:
            return _UNARY[type(node.op)](walk(node.operand))
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) \
                and node.func.id in _FUNCS and not node.keywords:
            return float(_FUNCS[node.func.id](*[walk(a) for a in node.args]))
        raise keyed_error(SceneError, where, "", "ex arithmetic", text=repr(text))

    try:
        value = walk(tree)
    except (ValueError, ZeroDivisionError, OverflowError, TypeError) as exc:
        raise keyed_error(SceneError, where, "", "ex cannot", text=repr(text), why=short(str(exc), 60)) from None
    if not math.isfinite(value):
        raise keyed_error(SceneError, where, "", "ex infinite", text=repr(text))
    return value


def _depth(tree: ast.AST) -> int:
    """The deepest chain of nodes in an expression's tree (walked without recursion)."""
    deepest, stack = 0, [(tree, 1)]
    while stack:
        node, depth = stack.pop()
        deepest = max(deepest, depth)
        stack.extend((child, depth + 1) for child in ast.iter_child_nodes(node))
    return deepest
