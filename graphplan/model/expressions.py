"""Safe arithmetic for scene parameters: ``"0.7 * rocker"``, ``"sqrt(2) * 0.1"``."""
from __future__ import annotations

import ast
import math
import operator

from graphplan.util.errors import SceneError

_BINARY = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
           ast.Div: operator.truediv, ast.Pow: operator.pow}
_UNARY = {ast.UAdd: operator.pos, ast.USub: operator.neg}
_FUNCS = {"sqrt": math.sqrt, "sin": math.sin, "cos": math.cos, "tan": math.tan,
          "asin": math.asin, "acos": math.acos, "atan": math.atan, "radians": math.radians,
          "degrees": math.degrees, "abs": abs}
_CONSTS = {"pi": math.pi}


def evaluate(text: str, names: dict[str, float], where: str) -> float:
    """Evaluate an arithmetic expression over numbers, known names and a few functions."""
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError:
        raise SceneError(f"cannot read the expression {text!r}", where) from None

    def walk(node: ast.AST) -> float:
        if isinstance(node, ast.Expression):
            return walk(node.body)
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) \
                and not isinstance(node.value, bool):
            return float(node.value)
        if isinstance(node, ast.Name):
            if node.id in names:
                return float(names[node.id])
            if node.id in _CONSTS:
                return _CONSTS[node.id]
            raise SceneError(f"unknown name {node.id!r} in {text!r}", where)
        if isinstance(node, ast.BinOp) and type(node.op) in _BINARY:
            return _BINARY[type(node.op)](walk(node.left), walk(node.right))
        if isinstance(node, ast.UnaryOp) and type(node.op) in _UNARY:
            return _UNARY[type(node.op)](walk(node.operand))
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) \
                and node.func.id in _FUNCS and not node.keywords:
            return float(_FUNCS[node.func.id](*[walk(a) for a in node.args]))
        raise SceneError(f"only arithmetic is allowed in {text!r}", where)

    try:
        value = walk(tree)
    except (ValueError, ZeroDivisionError, OverflowError, TypeError) as exc:
        raise SceneError(f"cannot evaluate {text!r}: {exc}", where) from None
    if not math.isfinite(value):
        raise SceneError(f"{text!r} is not a finite number", where)
    return value
