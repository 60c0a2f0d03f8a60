"""Type-check and ground expressions against a dungeon's objects.

Resolves every name (parameters, lets, constants, objects, enumeration values), inlines
propositional functions, expands quantifiers over finite classes (a grid quantifier whose
cell is pinned by `b.x == ...` conjuncts becomes one cell lookup), folds attributes that
no action changes into constants, and reports each type error at its position. Effects
are grounded by the `EffectGrounder` half (ground_effects.py); the values names stand for
besides IR are in ground_refs.py.
"""
from __future__ import annotations

import itertools

from ..errors import BccError
from . import ast, ir
from .definitions import ClassDef, Expr, table_row
from .dungeon import Dungeon
from .ground_effects import EffectGrounder
from .ground_refs import ClassName, Ctx, KeyRef, ObjRef, Table
from .limits import MAX_GRID_CELLS, MAX_GROUND_DEPTH, MAX_KEYED_OBJECTS
from .source import suggest

CMP_NUMERIC = {"<", "<=", ">", ">="}


class Grounder(EffectGrounder):
    """Grounds one dungeon. `dynamic` is the set of (class, attribute) pairs some action
    writes; None means "not known yet" (the discovery pass), so nothing is folded."""

    def __init__(self, dungeon: Dungeon, dynamic: set | None):
        self.d, self.dom, self.dynamic = dungeon, dungeon.domain, dynamic
        self.sizes = dungeon.sizes
        self.by_class = {c: [n for n, (oc, _) in dungeon.objects.items() if oc == c] for c in self.dom.classes}
        self.fresh = itertools.count()
        self.fresh_used = 0  # names `fresh` handed out (a call whose grounding takes none may be reused)
        self.depth = 0  # of `expr` calls in progress: bounds the nesting of the code emitted
        self.peak = 0   # the deepest `expr` call so far
        self.calls: dict = {}   # (function, its grounded arguments) -> (its grounding, nesting it took)
        self.writes: list = []  # (class, attr) or ("<grid>", y IR), recorded by effects
        self.effect_work = 0    # effect nodes grounded so far: bounds what nested first/forall multiply
        self.ranges: dict = {}  # (class, attribute) -> its range, once grounded
        self.key_ranges = {c.name: self._key_ranges(c) for c in self.dom.classes.values() if c.key}

    # ---- helpers ---------------------------------------------------------------------
    def next_fresh(self) -> int:
        """A number for a name no other grounding uses."""
        self.fresh_used += 1
        return next(self.fresh)

    def attr_range(self, cls: ClassDef, attr: str) -> tuple[int, int] | None:
        key = (cls.name, attr)
        if key not in self.ranges:   # its bounds are constant expressions: grounded once
            self.ranges[key] = self._attr_range(cls, attr)
        return self.ranges[key]

    def _attr_range(self, cls: ClassDef, attr: str) -> tuple[int, int] | None:
        adef = cls.attrs[attr]
        if adef.type == "bool":
            return (0, 1)
        if adef.type in self.dom.enums:
            return (0, len(self.dom.enums[adef.type].values) - 1)
        if adef.range is None:
            return None
        lo, hi = (self.const_int(e) for e in adef.range)
        if lo > hi:
            raise adef.range[0].error(f"empty range [{lo}, {hi}] for {cls.name}.{attr}")
        return lo, hi

    def const_int(self, src: Expr) -> int:
        value = self.expr(src.node, Ctx(src))
        if not (isinstance(value, ir.Const) and value.type == "int"):
            raise src.error("expected a constant integer (numbers, width, height, depth)")
        return int(value.value)

    def _key_ranges(self, cls: ClassDef):
        out, count = [], 1
        for k in cls.key:
            r = self.attr_range(cls, k)
            if r is None or cls.attrs[k].type != "int":
                raise BccError(f"key attribute {cls.name}.{k} needs an int `range`", self.dom.path)
            out.append(r)
            count *= r[1] - r[0] + 1
        limit = MAX_GRID_CELLS if self.is_grid(cls.name) else MAX_KEYED_OBJECTS
        if count > limit:
            src = cls.attrs[cls.key[-1]].range[0]
            raise src.error(f"the key of {cls.name!r} ranges over {count:,} objects; at most {limit:,}")
        return out

    def keys_of(self, cls: str) -> list[tuple]:
        return list(itertools.product(*(range(lo, hi + 1) for lo, hi in self.key_ranges[cls])))

    def is_grid(self, cls: str) -> bool:
        return cls == self.d.grid_class

    def is_dynamic(self, cls: str, attr: str) -> bool:
        return self.dynamic is None or (cls, attr) in self.dynamic

    def value_const(self, cls: str, attr: str, value) -> ir.Const:
        atype = self.dom.classes[cls].attrs[attr].type
        if atype in self.dom.enums:
            return ir.Const(self.dom.enums[atype].index(value), atype)
        return ir.Const(value, atype)

    def object_value(self, owner, cls: str, attr: str):
        """The initial value of an attribute, as given by the dungeon or its default."""
        cdef = self.dom.classes[cls]
        if isinstance(owner, tuple):
            _, key = owner
            return self.d.keyed.get(cls, {}).get(key, {}).get(attr, cdef.attrs[attr].default)
        return self.d.objects[owner][1].get(attr, cdef.attrs[attr].default)

    def read(self, owner, cls: str, attr: str):
        if self.is_dynamic(cls, attr):
            return ir.Var(ir.StateVar(owner, cls, attr, self.dom.classes[cls].attrs[attr].type))
        return self.value_const(cls, attr, self.object_value(owner, cls, attr))

    # ---- expressions -----------------------------------------------------------------
    def bool_expr(self, node, ctx: Ctx):
        value = self.expr(node, ctx, "bool")
        self.expect(value, "bool", node, ctx)
        return value

    def expect(self, value, want: str, node, ctx: Ctx):
        got = self.type_of(value)
        if got != want:
            raise ctx.error(node, f"type error: expected {want}, found {got}")

    def type_of(self, value) -> str:
        if isinstance(value, (ObjRef, KeyRef)):
            return value.cls
        if isinstance(value, ClassName):
            return f"the class {value.name}"
        if isinstance(value, Table):
            return f"the table {value.name}"
        return value.type

    def expr(self, node, ctx: Ctx, hint: str | None = None):
        method = getattr(self, "x_" + type(node).__name__)
        self.depth += 1
        if self.depth > self.peak:
            self.peak = self.depth
        try:
            if self.depth > MAX_GROUND_DEPTH:
                raise ctx.error(node, f"the expression is nested more than {MAX_GROUND_DEPTH} levels deep "
                                      "once the functions it calls are expanded")
            return method(node, ctx, hint)
        finally:
            self.depth -= 1

    def x_Int(self, node, ctx, hint):
        return ir.Const(node.value, "int")

    def x_Bool(self, node, ctx, hint):
        return ir.Const(node.value, "bool")

    def x_Name(self, node, ctx, hint):
        name = node.name
        enums = self.dom.enums
        if hint in enums and name in enums[hint].values:
            return ir.Const(enums[hint].index(name), hint)
        if hint in self.by_class and name in self.d.objects and self.d.objects[name][0] == hint:
            return ObjRef(name, hint)
        if name in ctx.env:
            return ctx.env[name]
        if name in self.sizes:
            return ir.Const(self.sizes[name], "int")
        if name in self.dom.constants:
            values = self.dom.constants[name]
            return ir.Const(values[0], "int") if len(values) == 1 else Table(name, values)
        if name in self.d.objects:
            return ObjRef(name, self.d.objects[name][0])
        owners = [e for e in enums.values() if name in e.values]
        if len(owners) == 1:
            return ir.Const(owners[0].index(name), owners[0].name)
        if len(owners) > 1:
            raise ctx.error(node, f"{name!r} is a value of several types ({', '.join(e.name for e in owners)}); "
                                  "compare it with a typed value so bcc knows which")
        if name in self.dom.classes:
            return ClassName(name)
        known = list(ctx.env) + list(self.sizes) + list(self.dom.constants) + list(self.d.objects) + \
            [v for e in enums.values() for v in e.values] + list(self.dom.classes)
        if name.lower() in ("true", "false"):   # Python's spelling
            raise ctx.error(node, f"unknown name {name!r} (did you mean '{name.lower()}'?)")
        raise ctx.error(node, f"unknown name {name!r}{suggest(name, known)}")

    def x_Attr(self, node, ctx, hint):
        obj = self.expr(node.obj, ctx)
        if isinstance(obj, (ObjRef, KeyRef)):
            cdef = self.dom.classes[obj.cls]
            if node.name not in cdef.attrs:
                raise ctx.error(node, f"class {obj.cls!r} has no attribute {node.name!r}{suggest(node.name, cdef.attrs)}")
            return self.attr_of(obj, node.name, node, ctx)
        otype = self.type_of(obj)
        if otype in self.dom.enums:
            enum = self.dom.enums[otype]
            if node.name not in enum.properties:
                raise ctx.error(node, f"type {otype!r} has no property {node.name!r}{suggest(node.name, enum.properties)}")
            ptype = enum.prop_types.get(node.name, "int")
            label = f"{otype}.{node.name}"
            if node.name in enum.prop_per:   # a table: indexed next, `r.uses[m]`
                per = enum.prop_per[node.name]
                if isinstance(obj, ir.Const):
                    return Table(label, table_row(self.dom.enums, enum, node.name, obj.value), per, ptype)
                rows = [table_row(self.dom.enums, enum, node.name, i) for i in range(len(enum.values))]
                return Table(label, tuple(v for r in rows for v in r), per, ptype, obj, len(self.dom.enums[per].values))
            table = tuple(enum.properties[node.name])
            if isinstance(obj, ir.Const):
                return ir.Const(table[obj.value], ptype)
            return ir.Lookup(table, obj, ptype, label)
        raise ctx.error(node, f"type error: {otype} has no attribute {node.name!r}")

    def attr_of(self, obj, attr: str, node, ctx):
        cls = self.dom.classes[obj.cls]
        atype = cls.attrs[attr].type
        if isinstance(obj, ObjRef) and obj.name is None:  # a symbolic object (check_domain)
            return ir.Local(f"__{obj.cls}_{attr}", atype)
        if isinstance(obj, ObjRef):
            return self.read(obj.name, obj.cls, attr)
        if attr in cls.key:
            return obj.keys[cls.key.index(attr)]
        if self.is_grid(obj.cls):
            return ir.Cell(*obj.keys, atype)
        if all(isinstance(k, ir.Const) for k in obj.keys):
            key = tuple(k.value for k in obj.keys)
            if key not in set(self.keys_of(obj.cls)):
                raise ctx.error(node, f"{obj.cls}{list(key)} does not exist (keys range over {self.key_ranges[obj.cls]})")
            return self.read((obj.cls, key), obj.cls, attr)
        if len(cls.key) != 1:
            raise ctx.error(node, f"a run-time key into {obj.cls!r} needs a class keyed by one attribute")
        if self.is_dynamic(obj.cls, attr):
            return ir.VarAt(obj.cls, obj.keys[0], attr, atype)
        lo = self.key_ranges[obj.cls][0][0]
        values = tuple(self.value_const(obj.cls, attr, self.object_value((obj.cls, k), obj.cls, attr)).value
                       for k in self.keys_of(obj.cls))
        index = obj.keys[0] if lo == 0 else ir.Arith("-", obj.keys[0], ir.Const(lo, "int"))
        return ir.Lookup(values, index, atype, f"{obj.cls}[].{attr}")

    def x_Index(self, node, ctx, hint):
        obj = self.expr(node.obj, ctx)
        if isinstance(obj, ClassName):
            cdef = self.dom.classes[obj.name]
            if not cdef.key:
                raise ctx.error(node, f"class {obj.name!r} has no `key`, so it cannot be indexed; name its objects instead")
            if len(node.args) != len(cdef.key):
                raise ctx.error(node, f"{obj.name}[...] takes {len(cdef.key)} key(s) ({', '.join(cdef.key)}), found {len(node.args)}")
            keys = []
            for arg in node.args:
                k = self.expr(arg, ctx, "int")
                self.expect(k, "int", arg, ctx)
                keys.append(k)
            return KeyRef(obj.name, tuple(keys))
        if isinstance(obj, Table):
            if len(node.args) != 1:
                raise ctx.error(node, f"the table {obj.name!r} takes one index")
            index = self.expr(node.args[0], ctx, obj.index_type)
            if self.type_of(index) != obj.index_type:
                raise ctx.error(node.args[0], f"type error: the table {obj.name!r} is indexed by "
                                              f"{obj.index_type}, found {self.type_of(index)}")
            if obj.row is not None:   # a run-time row: one lookup in the rows laid end to end
                at = ir.Arith("+", ir.Arith("*", obj.row, ir.Const(obj.width, "int")), index)
                return ir.Lookup(obj.values, at, obj.value_type, obj.name)
            if isinstance(index, ir.Const):
                if not 0 <= index.value < len(obj.values):
                    raise ctx.error(node, f"index {index.value} is outside the table {obj.name!r} (size {len(obj.values)})")
                return ir.Const(obj.values[index.value], obj.value_type)
            return ir.Lookup(obj.values, index, obj.value_type, obj.name)
        raise ctx.error(node, f"type error: {self.type_of(obj)} cannot be indexed")

    def x_Call(self, node, ctx, hint):
        fdef = self.dom.functions.get(node.func)
        if fdef is None:
            raise ctx.error(node, f"unknown function {node.func!r}{suggest(node.func, self.dom.functions)}")
        if node.func in ctx.stack:
            cycle = " -> ".join(ctx.stack[ctx.stack.index(node.func):] + (node.func,))
            raise ctx.error(node, f"function {node.func!r} calls itself ({cycle}); functions are "
                                  "expanded inline, so they cannot be recursive")
        if len(node.args) != len(fdef.params):
            raise ctx.error(node, f"{node.func} takes {len(fdef.params)} argument(s) "
                                  f"({', '.join(p.name + ': ' + p.type for p in fdef.params)}), found {len(node.args)}")
        bound, by_type = {}, []
        for param, arg in zip(fdef.params, node.args):
            value = self.expr(arg, ctx, param.type)
            vtype = self.type_of(value)
            if vtype != param.type:
                cdef = self.dom.classes.get(param.type)
                value_attrs = [a for a in cdef.attrs if a not in cdef.key] if cdef and cdef.key else []
                if len(value_attrs) == 1 and cdef.attrs[value_attrs[0]].type == vtype:
                    by_type.append((param, value_attrs[0], value))  # a type for a keyed object: some object of that type
                    continue
                raise ctx.error(arg, f"type error: argument {param.name!r} of {node.func} is {param.type}, found {vtype}")
            bound[param.name] = value
        if by_type:
            return self.call_by_type(node, ctx, fdef, bound, by_type)
        return self.expand_call(node, ctx, fdef, bound)

    def expand_call(self, node, ctx, fdef, bound: dict):
        """The function's body with its parameters bound. A body depends on nothing but its
        arguments, so a call repeated with the same grounded arguments (`roomFor(t)` once per
        item a move may pick up; arguments that are names, constants or state variables)
        reuses the first grounding: the same IR, unless the first
        took fresh names (those are handed out again) or the repeat runs deeper than the
        nesting bound allows (then it is grounded again, to raise the error)."""
        key = hit = None
        if all(type(v) in _SHALLOW for v in bound.values()):   # deep arguments cost more to hash than they save
            key = (fdef.name, tuple(bound.items()))
            hit = self.calls.get(key)
        if hit is not None and self.depth + hit[1] <= MAX_GROUND_DEPTH:
            self.peak = max(self.peak, self.depth + hit[1])
            return hit[0]
        inner = Ctx(fdef.body, bound, ctx.stack + (node.func,))
        used, peak, self.peak = self.fresh_used, self.peak, self.depth
        try:
            value = self.expr(fdef.body.node, inner)
        except BccError as exc:
            if exc.path == fdef.body.where.path and ctx.src.where.path != exc.path:
                exc.message += f" (in {node.func}, called at {ctx.src.where.path}:{ctx.src.where.locate(*node.pos)[0]})"
            raise
        finally:
            deeper, self.peak = self.peak - self.depth, max(peak, self.peak)
        if key is not None and self.fresh_used == used:
            self.calls[key] = (value, deeper)
        return value

    def call_by_type(self, node, ctx, fdef, bound, by_type):
        """f(..., T, ...) where f wants a keyed object and T is a value of its value attribute:
        `exists b in C . b.value == T and f(..., b, ...)` (a block type means "some block of that type")."""
        env = dict(ctx.env)
        args, conds = [], []
        by_name = {p.name: (attr, value) for p, attr, value in by_type}
        for param in fdef.params:
            fresh = f"__{param.name}{self.next_fresh()}"
            if param.name in by_name:
                attr, value = by_name[param.name]
                tname = fresh + "t"
                env[tname] = value
                conds.append((fresh, param.type, attr, tname))
            else:
                env[fresh] = bound[param.name]
            args.append(ast.Name(fresh, node.pos))
        body: ast.Node = ast.Call(fdef.name, tuple(args), node.pos)
        for fresh, cls, attr, tname in reversed(conds):
            test = ast.Compare((ast.Attr(ast.Name(fresh, node.pos), attr, node.pos), ast.Name(tname, node.pos)), ("==",), node.pos)
            body = ast.Quantifier("exists", fresh, cls, ast.And(test, body, node.pos), node.pos)
        return self.expr(body, Ctx(ctx.src, env, ctx.stack))

    def x_Neg(self, node, ctx, hint):
        v = self.expr(node.operand, ctx, "int")
        self.expect(v, "int", node.operand, ctx)
        return ir.Const(-v.value, "int") if isinstance(v, ir.Const) else ir.Neg(v)

    def x_BinOp(self, node, ctx, hint):
        left = self.expr(node.left, ctx, "int")
        right = self.expr(node.right, ctx, "int")
        self.expect(left, "int", node.left, ctx)
        self.expect(right, "int", node.right, ctx)
        if node.op in ("//", "%") and isinstance(right, ir.Const) and right.value == 0:
            raise ctx.error(node, "division by zero")
        if isinstance(left, ir.Const) and isinstance(right, ir.Const):
            a, b = left.value, right.value
            return ir.Const({"+": a + b, "-": a - b, "*": a * b, "//": a // b, "%": a % b}[node.op], "int")
        if node.op in "+-" and isinstance(right, ir.Const) and right.value == 0:
            return left
        if node.op in ("//", "%") and not isinstance(right, ir.Const):   # its place, should it be 0 at run time
            return ir.Arith(node.op, left, right, "int", str(ctx.error(node, f"`{node.op}` by zero")))
        return ir.Arith(node.op, left, right)

    def x_Compare(self, node, ctx, hint):
        values = []
        first, k = None, 0
        for i, operand in enumerate(node.operands):
            v = self.expr(operand, ctx, hint=first)
            if first is None and self.type_of(v) in self.dom.enums:
                first, k = self.type_of(v), i
            values.append(v)
        if first is not None:  # resolve bare value names against the left operand's type
            # (only a name reads the hint; operands after the k-th were given it already)
            values = [self.expr(o, ctx, hint=first) if i <= k and isinstance(o, ast.Name) else v
                      for i, (o, v) in enumerate(zip(node.operands, values))]
        for op, (ln, lv), (rn, rv) in zip(node.ops, zip(node.operands, values), zip(node.operands[1:], values[1:])):
            lt, rt = self.type_of(lv), self.type_of(rv)
            if isinstance(lv, (ObjRef, KeyRef, ClassName, Table)) or isinstance(rv, (ObjRef, KeyRef, ClassName, Table)):
                raise ctx.error(node, f"type error: cannot compare {lt} with {rt}; compare their attributes")
            if op in CMP_NUMERIC and (lt != "int" or rt != "int"):
                raise ctx.error(node, f"type error: {op!r} needs two ints, found {lt} and {rt}")
            if lt != rt:
                raise ctx.error(node, f"type error: cannot compare {lt} with {rt}")
        if all(isinstance(v, ir.Const) for v in values):
            ok = all(_cmp(op, a.value, b.value) for op, a, b in zip(node.ops, values, values[1:]))
            return ir.Const(ok, "bool")
        if len(node.ops) == 1:
            known = self.by_range(node.ops[0], *values)
            if known is not None:
                return ir.Const(known, "bool")
        return ir.Cmp(tuple(node.ops), tuple(values))

    def by_range(self, op: str, left, right) -> bool | None:
        """`attribute op constant` (either way round) decided by the attribute's declared
        range alone (`s.count >= 0` where count ranges over [0, 64]), else None."""
        if isinstance(left, ir.Const):
            left, right, op = right, left, {"<": ">", "<=": ">=", ">": "<", ">=": "<="}.get(op, op)
        if not (isinstance(left, ir.Var) and isinstance(right, ir.Const) and left.type == "int"):
            return None
        rng = self.attr_range(self.dom.classes[left.var.cls], left.var.attr)
        if rng is None:
            return None
        lo, hi = rng
        outcomes = {_cmp(op, lo, right.value), _cmp(op, hi, right.value)}
        if op in ("==", "!=") and lo <= right.value <= hi:
            return None
        return outcomes.pop() if len(outcomes) == 1 else None

    def x_And(self, node, ctx, hint):
        return make_bool("and", [self.bool_expr(node.left, ctx), self.bool_expr(node.right, ctx)])

    def x_Or(self, node, ctx, hint):
        return make_bool("or", [self.bool_expr(node.left, ctx), self.bool_expr(node.right, ctx)])

    def x_Not(self, node, ctx, hint):
        v = self.bool_expr(node.operand, ctx)
        return ir.Const(not v.value, "bool") if isinstance(v, ir.Const) else ir.Not(v)

    def x_Quantifier(self, node, ctx, hint):
        cls = node.cls
        if cls not in self.dom.classes:
            raise ctx.error(node, f"unknown class {cls!r}{suggest(cls, self.dom.classes)}")
        op = "or" if node.kind == "exists" else "and"
        if self.is_grid(cls):
            return self.grid_quantifier(node, ctx)
        items = [self.bool_expr(node.body, ctx.bind(**{node.var: ref})) for ref in self.objects_of(cls)]
        return make_bool(op, items)

    def objects_of(self, cls: str) -> list:
        if self.dom.classes[cls].key:
            return [KeyRef(cls, tuple(ir.Const(k, "int") for k in key)) for key in self.keys_of(cls)]
        return [ObjRef(name, cls) for name in self.by_class[cls]]

    def grid_quantifier(self, node, ctx):
        """Over every cell, unless `exists` conjuncts pin each key (`b.x == a.x and ...`):
        then it is one lookup of that cell, guarded by the key ranges."""
        cdef = self.dom.classes[node.cls]
        n = self.next_fresh()
        names = tuple(f"q{n}_{k}" for k in cdef.key)
        ref = KeyRef(node.cls, tuple(ir.Local(nm, "int") for nm in names))
        body = self.bool_expr(node.body, ctx.bind(**{node.var: ref}))
        if isinstance(body, ir.Const):
            return body
        if node.kind == "exists":
            items = list(body.items) if isinstance(body, ir.BoolOp) and body.op == "and" else [body]
            pins, rest = {}, []
            for item in items:
                pin = _pin(item, names)
                if pin and pin[0] not in pins:
                    pins[pin[0]] = pin[1]
                else:
                    rest.append(item)
            if len(pins) == len(names):
                guards = [self.in_range(pins[nm], lo, hi) for nm, (lo, hi) in zip(names, self.key_ranges[node.cls])]
                return make_bool("and", guards + [ir.substitute(r, pins) for r in rest])
        return ir.CellLoop(node.kind, names, body)

    def in_range(self, value, lo: int, hi: int):
        """`lo <= value <= hi`, folded to true when the value's own range guarantees it."""
        if isinstance(value, ir.Var):
            r = self.attr_range(self.dom.classes[value.var.cls], value.var.attr)
            if r is not None and lo <= r[0] and r[1] <= hi:
                return ir.TRUE
        return _in_range(value, lo, hi)

    def symbolic(self, params) -> dict:
        """Stand-ins for parameters, to type-check a body without grounding it."""
        env = {}
        for p in params:
            cdef = self.dom.classes.get(p.type)
            if cdef is None:
                env[p.name] = ir.Local(f"__{p.name}", p.type)
            elif cdef.key:
                env[p.name] = KeyRef(p.type, tuple(ir.Local(f"__{p.name}_{k}", "int") for k in cdef.key))
            else:
                env[p.name] = ObjRef(None, p.type)
        return env

    def check_domain(self) -> None:
        """Type-check every function and every action schema once, called or not."""
        for fdef in self.dom.functions.values():
            self.expr(fdef.body.node, Ctx(fdef.body, self.symbolic(fdef.params), (fdef.name,)))
        for schema in self.dom.actions.values():
            env = self.symbolic(schema.params)
            for name, src in schema.lets:
                env[name] = self.expr(src.node, Ctx(src, env))
            for src in schema.pre:
                self.bool_expr(src.node, Ctx(src, env))
            self.effects(schema.effects.node, Ctx(schema.effects, env))



_SHALLOW = (ObjRef, ir.Const, ir.Var, ir.Local)   # arguments a call's grounding is reused for


def _cmp(op, a, b) -> bool:
    return {"==": a == b, "!=": a != b, "<": a < b, "<=": a <= b, ">": a > b, ">=": a >= b}[op]


def make_bool(op: str, items: list):
    """and/or with constant folding and flattening."""
    absorbing = op == "or"  # True absorbs `or`, False absorbs `and`
    out = []
    for item in items:
        if isinstance(item, ir.Const):
            if bool(item.value) == absorbing:
                return ir.Const(absorbing, "bool")
            continue
        if isinstance(item, ir.BoolOp) and item.op == op:
            out.extend(item.items)
        else:
            out.append(item)
    if not out:
        return ir.Const(not absorbing, "bool")
    return out[0] if len(out) == 1 else ir.BoolOp(op, tuple(out))



def _in_range(value, lo: int, hi: int):
    if isinstance(value, ir.Const):
        return ir.Const(lo <= value.value <= hi, "bool")
    return ir.Cmp(("<=", "<="), (ir.Const(lo, "int"), value, ir.Const(hi, "int")))


def _pin(cond, names: tuple):
    """`q == E` (or `E == q`) for a loop variable q, with E free of loop variables: (q, E)."""
    if not (isinstance(cond, ir.Cmp) and cond.ops == ("==",)):
        return None
    left, right = cond.operands
    for a, b in ((left, right), (right, left)):
        if isinstance(a, ir.Local) and a.name in names and not (ir.locals_of(b) & set(names)):
            return a.name, b
    return None
