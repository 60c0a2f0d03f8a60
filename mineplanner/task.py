"""Read one MinePlanner task (its propositional domain and problem PDDL) into plain data.

Why not bcc's PDDL front end: that grounds the task, which is what is too big here; this
edge only needs the world the problem describes (blocks and items with positions, the
agent, its counts) and what `checkgoal` asks for, so it reads the s-expressions
(pddl_io/read.py, with positions for errors) and names the facts it understands.

Coordinates are read from the `are-seq` chains, not from object names: the first
position of the chain is 0, and so are counts. Mistakes are one line `file:line:col`.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from ..errors import BccError
from ..pddl_io.read import read_sexpr

BLOCK_SUFFIX = "-block"


@dataclass
class Task:
    name: str
    agent: str                         # the agent object
    agent_at: tuple                    # (x, y, z) chain indices
    blocks: dict                       # (x, y, z) -> (object, material) of present blocks
    spare: dict                        # material -> [block objects not present], in file order
    items: list                        # [(object, material, (x, y, z))] present items, in file order
    counts: dict                       # material -> count the agent holds (one per item type)
    positions: list                    # position objects, chain order (index = coordinate)
    count_objects: list                # count objects, chain order (index = value)
    goal: object                       # the checkgoal precondition, an s-expression
    block_types: dict = field(default_factory=dict)   # block type -> material ("bedrock" -> "bedrock")
    paths: tuple = ()                  # (domain file, problem file)


def _error(path: str, node, message: str) -> BccError:
    line, column = getattr(node, "line", 0), getattr(node, "column", 0)
    return BccError(message, path, line or None, column or None)


def _section(tree, key: str, path: str, required: bool = True):
    for part in tree[2:] if isinstance(tree, list) else ():
        if isinstance(part, list) and part and part[0] == key:
            return part
    if required:
        raise _error(path, tree, f"no `({key} ...)` section")
    return None


def _typed(names: list) -> list[tuple]:
    """[(name, type)] of a PDDL typed list `a b - t c - u`."""
    out, pending, i = [], [], 0
    while i < len(names):
        if names[i] == "-" and i + 1 < len(names):
            out += [(n, names[i + 1]) for n in pending]
            pending, i = [], i + 2
        else:
            pending.append(names[i])
            i += 1
    return out + [(n, "object") for n in pending]


def _chain(pairs: list, members: set, what: str, path: str, where) -> list:
    """The objects of one `are-seq` chain in order (each pair is (earlier, later))."""
    nxt = {a: b for a, b in pairs if a in members and b in members}
    starts = [m for m in members if m not in set(nxt.values())]
    if len(starts) != 1:
        raise _error(path, where, f"the {what} objects do not form one `are-seq` chain ({len(starts)} starts)")
    order = [starts[0]]
    while order[-1] in nxt and len(order) <= len(members):
        order.append(nxt[order[-1]])
    if len(order) != len(members):
        raise _error(path, where, f"the {what} chain of `are-seq` misses {len(members) - len(order)} objects")
    return order


def read_task(domain_path: str, problem_path: str) -> Task:
    domain = _one(read_sexpr(domain_path), domain_path)
    problem = _one(read_sexpr(problem_path), problem_path)
    for tree, path, kind in ((domain, domain_path, "domain"), (problem, problem_path, "problem")):
        if not (isinstance(tree, list) and len(tree) >= 2 and tree[0] == "define"
                and isinstance(tree[1], list) and tree[1][:1] == [kind]):
            raise _error(path, tree, f"expected `(define ({kind} NAME) ...)`")
    materials, block_types = _types(domain, domain_path)
    goal = _checkgoal(domain, domain_path)
    objects = _typed(list(_section(problem, ":objects", problem_path)[1:]))
    init = _section(problem, ":init", problem_path)
    facts = [f for f in init[1:] if isinstance(f, list) and f and f[0] != "not"]
    by_pred: dict = {}
    for f in facts:
        by_pred.setdefault(f[0], []).append(f)
    seq = [(f[1], f[2]) for f in by_pred.get("are-seq", []) if len(f) == 3]
    positions = _chain(seq, {n for n, t in objects if t == "position"}, "position", problem_path, init)
    counts = _chain(seq, {n for n, t in objects if t == "count"}, "count", problem_path, init)
    pos_index = {p: i for i, p in enumerate(positions)}
    count_index = {c: i for i, c in enumerate(counts)}

    coords: dict = {}
    for axis, pred in enumerate(("at-x", "at-y", "at-z")):
        for f in by_pred.get(pred, []):
            if len(f) != 3 or f[2] not in pos_index:
                raise _error(problem_path, f, f"`({pred} OBJECT POSITION)` names no position")
            coords.setdefault(f[1], [None] * 3)[axis] = pos_index[f[2]]
    agents = [n for n, t in objects if t == "agent"]
    if len(agents) != 1:
        raise _error(problem_path, init, f"the task has {len(agents)} agents; one is supported")
    agent = agents[0]

    def where(name, node):
        c = coords.get(name)
        if c is None or None in c:
            raise _error(problem_path, node, f"{name} has no complete position (at-x, at-y, at-z)")
        return tuple(c)

    present = {f[1] for f in by_pred.get("block-present", [])}
    blocks, spare = {}, {m: [] for m in materials}
    for name, t in objects:
        if t not in block_types:
            continue
        material = block_types[t]
        if name in present:
            at = where(name, init)
            if at in blocks:
                raise _error(problem_path, init, f"two blocks at one place: {blocks[at][0]} and {name}")
            blocks[at] = (name, material)
        elif material in spare:
            spare[material].append(name)
    lying = {f[1] for f in by_pred.get("item-present", [])}
    items = [(name, t, where(name, init)) for name, t in objects if t in materials and name in lying]
    held = {m: 0 for m in materials}
    for pred, fs in by_pred.items():
        if pred.startswith("agent-has-n-") and pred[len("agent-has-n-"):] in held:
            for f in fs:
                if f[1] == agent:
                    held[pred[len("agent-has-n-"):]] = count_index[f[2]]
    name = problem[1][1] if len(problem[1]) > 1 else "task"
    return Task(str(name), agent, where(agent, init), blocks, spare, items, held, positions, counts, goal,
                block_types, (domain_path, problem_path))


def _one(forms: list, path: str):
    if len(forms) != 1:
        raise _error(path, forms[1] if len(forms) > 1 else None, "a PDDL file holds one `(define ...)`")
    return forms[0]


def _types(domain, path: str) -> tuple[set, dict]:
    """The item types (materials) and block types (`T-block` of a material, and `bedrock`)."""
    section = _section(domain, ":types", path)
    typed = _typed(list(section[1:]))
    materials = {n for n, t in typed if t == "item"}
    block_types = {}
    for n, t in typed:
        if t == "destructible-block" and n.endswith(BLOCK_SUFFIX) and n[:-len(BLOCK_SUFFIX)] in materials:
            block_types[n] = n[:-len(BLOCK_SUFFIX)]
        elif t == "block" and n != "destructible-block":
            block_types[n] = str(n)          # an indestructible block type (bedrock)
        elif t == "destructible-block":
            raise _error(path, n, f"the block type {n} is not `MATERIAL-block` of an item type")
    return materials, block_types


def _checkgoal(domain, path: str):
    for part in domain[2:]:
        if isinstance(part, list) and part[:2] == [":action", "checkgoal"]:
            keys = {part[i]: part[i + 1] for i in range(2, len(part) - 1, 2)}
            if ":precondition" not in keys:
                raise _error(path, part, "the `checkgoal` action has no precondition")
            return keys[":precondition"]
    raise _error(path, domain, "no `checkgoal` action: MinePlanner's goal is its precondition")
