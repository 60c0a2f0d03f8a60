"""Ground an action's effects: assignments, `if`, `first`, `forall`, `add` and `remove`
become IR writes (`SetVar`, `SetVarAt`, `SetCell`) under `When` conditions.

A mixin of `Grounder` (ground.py), which grounds the expressions effects read; kept apart
because effects are their own small language: what may be assigned, range checks of
constant writes, and the bounds on how much nested `first`/`forall` may multiply.
"""
from __future__ import annotations

from . import ast, ir
from .definitions import Expr
from .ground_refs import Ctx, KeyRef, ObjRef
from .limits import MAX_EFFECT_LEVELS, MAX_GENERATED_NESTING, MAX_GROUND_EFFECTS
from .source import suggest


class EffectGrounder:
    """The effect half of `Grounder`: `effects(nodes, ctx)` is the IR of an effect list;
    every write is recorded in `self.writes`."""

    def effects(self, nodes, ctx: Ctx) -> tuple:
        out = []
        for node in nodes:
            self.effect_work += 1
            if self.effect_work > MAX_GROUND_EFFECTS:   # nested `first`/`forall` multiply: 20 deep over 9 objects is 9^20
                raise ctx.error(node, f"the effects expand to more than {MAX_GROUND_EFFECTS:,} ground effects "
                                      "(each `first` and `forall` repeats its body once per object, and nested "
                                      "ones multiply)")
            out.extend(getattr(self, "e_" + type(node).__name__)(node, ctx))
        return tuple(out)

    def e_Assign(self, node, ctx):
        target = node.target
        if not isinstance(target, ast.Attr):
            raise ctx.error(node, "only attributes can be assigned, e.g. `a.x = tx`")
        obj = self.expr(target.obj, ctx)
        if not isinstance(obj, (ObjRef, KeyRef)):
            raise ctx.error(target, f"type error: {self.type_of(obj)} has no attributes to assign")
        cdef = self.dom.classes[obj.cls]
        if target.name not in cdef.attrs:
            raise ctx.error(target, f"class {obj.cls!r} has no attribute {target.name!r}{suggest(target.name, cdef.attrs)}")
        if target.name in cdef.key:
            raise ctx.error(target, f"{target.name!r} is a key of {obj.cls!r}: use `add`/`remove` to move such objects")
        atype = cdef.attrs[target.name].type
        value = self.expr(node.value, ctx, atype)
        if self.type_of(value) != atype:
            raise ctx.error(node.value, f"type error: {obj.cls}.{target.name} is {atype}, found {self.type_of(value)}")
        return [self.write(obj, target.name, value, node, ctx)]

    def write(self, obj, attr: str, value, node, ctx):
        if isinstance(obj, KeyRef) and self.is_grid(obj.cls):
            self.writes.append(("<grid>", obj.keys[1]))
            return ir.SetCell(*obj.keys, value)
        self.writes.append((obj.cls, attr))
        cdef = self.dom.classes[obj.cls]
        if isinstance(value, ir.Const) and cdef.attrs[attr].type == "int":
            rng = self.attr_range(cdef, attr)
            if rng is not None and not rng[0] <= value.value <= rng[1]:
                raise ctx.error(node, f"an effect sets {obj.cls}.{attr} to {value.value}, "
                                      f"outside its range [{rng[0]}, {rng[1]}]")
        if isinstance(obj, ObjRef):
            return ir.SetVar(ir.StateVar(obj.name, obj.cls, attr, value.type), value)
        if all(isinstance(k, ir.Const) for k in obj.keys):
            key = tuple(k.value for k in obj.keys)
            if key not in set(self.keys_of(obj.cls)):
                raise ctx.error(node, f"{obj.cls}{list(key)} does not exist")
            return ir.SetVar(ir.StateVar((obj.cls, key), obj.cls, attr, value.type), value)
        if len(obj.keys) != 1:
            raise ctx.error(node, f"a run-time key into {obj.cls!r} needs a class keyed by one attribute")
        return ir.SetVarAt(obj.cls, obj.keys[0], attr, value)

    def e_If(self, node, ctx):
        orelse = self.effects(node.orelse, ctx)
        for cond, body in reversed(node.branches):
            c = self.bool_expr(cond, ctx)
            orelse = when(c, self.effects(body, ctx), orelse)
        return list(orelse)

    def e_First(self, node, ctx):
        self.check_class(node, ctx)
        if self.is_grid(node.cls):
            raise ctx.error(node, "`first` over the grid class is not supported; name the cell with block[x, y, z]")
        orelse = self.effects(node.orelse, ctx)
        for ref in reversed(self.objects_of(node.cls)):
            inner = ctx.bind(**{node.var: ref})
            orelse = when(self.bool_expr(node.cond, inner), self.effects(node.body, inner), orelse)
        return list(orelse)

    def e_ForEach(self, node, ctx):
        self.check_class(node, ctx)
        if self.is_grid(node.cls):
            raise ctx.error(node, "`forall` effects over the grid class are not supported")
        out = []
        for ref in self.objects_of(node.cls):
            inner = ctx.bind(**{node.var: ref})
            cond = self.bool_expr(node.cond, inner) if node.cond is not None else ir.TRUE
            out.extend(when(cond, self.effects(node.body, inner), ()))
        return out

    def check_class(self, node, ctx):
        if node.cls not in self.dom.classes:
            raise ctx.error(node, f"unknown class {node.cls!r}{suggest(node.cls, self.dom.classes)}")

    def keyed_target(self, node, target, ctx) -> KeyRef:
        obj = self.expr(target, ctx)
        if not isinstance(obj, KeyRef):
            raise ctx.error(node, "`add` and `remove` take an object of a keyed class, e.g. block[x, y, z]")
        return obj

    def e_Add(self, node, ctx):
        obj = self.keyed_target(node, node.target, ctx)
        cdef = self.dom.classes[obj.cls]
        inits = dict(node.inits)
        for name in inits:
            if name not in cdef.attrs or name in cdef.key:
                raise ctx.error(node, f"{obj.cls!r} has no non-key attribute {name!r}{suggest(name, cdef.attrs)}")
        out = []
        for attr, adef in cdef.attrs.items():
            if attr in cdef.key:
                continue
            if attr in inits:
                value = self.expr(inits[attr], ctx, adef.type)
                if self.type_of(value) != adef.type:
                    raise ctx.error(inits[attr], f"type error: {obj.cls}.{attr} is {adef.type}, found {self.type_of(value)}")
            else:
                value = self.value_const(obj.cls, attr, adef.default)
            out.append(self.write(obj, attr, value, node, ctx))
        return out

    def e_Remove(self, node, ctx):
        obj = self.keyed_target(node, node.target, ctx)
        cdef = self.dom.classes[obj.cls]
        return [self.write(obj, attr, self.value_const(obj.cls, attr, adef.default), node, ctx)
                for attr, adef in cdef.attrs.items() if attr not in cdef.key]



def when(cond, then: tuple, orelse: tuple) -> tuple:
    if isinstance(cond, ir.Const):
        return tuple(then) if cond.value else tuple(orelse)
    if not then and not orelse:
        return ()
    return (ir.When(cond, tuple(then), tuple(orelse)),)



def check_nesting(name: str, pre: list, effects: tuple, where: Expr) -> None:
    """Each precondition and each conditional effect is one more indented block of the
    generated Python, which allows at most 100: refuse an action that would need more. An
    elif chain (a `first` over objects is one branch per object) is one block of `if ...
    elif ...`, but Python's compiler and the analyses still go one level deeper per branch:
    those levels are bounded apart, by MAX_EFFECT_LEVELS."""
    depth = levels = 0
    todo = [(e, 1, 1) for e in effects]      # (effect, its indented block, its level counting branches)
    while todo:
        e, block, level = todo.pop()
        if isinstance(e, ir.When):
            depth, levels = max(depth, block), max(levels, level)
            todo += [(x, block + 1, level + 1) for x in e.then]
            chained = len(e.orelse) == 1 and isinstance(e.orelse[0], ir.When)
            todo += [(x, block if chained else block + 1, level + 1) for x in e.orelse]
    if len(pre) + depth > MAX_GENERATED_NESTING:
        raise where.error(f"action {name}: {len(pre)} preconditions and effects nested {depth} deep "
                          f"exceed {MAX_GENERATED_NESTING} levels")
    if levels > MAX_EFFECT_LEVELS:
        raise where.error(f"action {name}: its conditional effects are nested {levels} deep (each elif and "
                          f"each object of a `first` is one level) and exceed {MAX_EFFECT_LEVELS} levels")
