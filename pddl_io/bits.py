"""Python source for an imported task's IR, with a state as one int: bit i is atom i.

Why an int and not one byte per atom: an action is then `s & ~deletes | adds`, two
integer operations instead of copying a bytearray, writing each changed byte and
freezing it again (about three times faster per successor), and a state of 285 atoms
takes about 64 bytes instead of 318 (mystery p02 stores millions of them). Conditions
test masks: a conjunction of atoms is `s & M == M`, of negated atoms `not s & M`.
PDDL semantics: every condition reads the state before the action; deletes apply
before adds, so an atom both deleted and added holds afterwards.

Successors are a decision tree (Fast Downward's successor generator): actions are
grouped under a test of a positive precondition atom they share, most frequent first,
so a state only looks at actions whose first atoms hold. Only numbers (hexadecimal
masks and action indices) reach the source: no text from the PDDL files.
"""
from __future__ import annotations

from collections import Counter

from ..compiler import ir

MAX_DEPTH = 40     # atoms on a path of the decision tree
MAX_NESTING = 80   # Python's parser allows 100 levels of indentation: groups stop at 80
FAN = 4            # a wide node's children are tested in this many groups, recursively


def _tree_by_frequency(keys: list) -> dict:
    """Each action's atoms, most frequent (over all actions) first, as a path from the
    root: a node maps an atom to its subtree, and None to the actions that end there."""
    freq = Counter(i for k in keys for i in k)
    root: dict = {}
    for i, k in enumerate(keys):
        node = root
        for atom in sorted(set(k), key=lambda t: (-freq[t], t))[:MAX_DEPTH]:
            node = node.setdefault(atom, {})
        node.setdefault(None, []).append(i)
    return root


def _tree_by_pruning(keys: list, prob: dict) -> dict:
    """The same kind of tree, each node's tests chosen for what they prune: the next test
    is the atom that most of the node's remaining actions need, weighted by how often
    it is false (`prob`: atom -> share of sampled states where it holds). An atom that
    nearly always holds is worth little as a test; a rarely true one shared by many
    actions skips them all at once (freecell p3: 80 tests a state instead of 120)."""
    weight = {a: 1.0001 - p for a, p in prob.items()}

    def build(idx, used):
        if len(idx) == 1:          # one action: its leaf tests its other atoms in one mask
            return {None: list(idx)}
        node: dict = {}
        rem = [(i, [a for a in keys[i] if a not in used]) for i in idx]
        here = [i for i, r in rem if not r or len(used) >= MAX_DEPTH]
        if here:
            node[None] = here
        count: dict = {}
        needing: dict = {}        # atom -> the actions (not in `here`) that need it
        for i, r in rem:
            if r and len(used) < MAX_DEPTH:
                for a in r:
                    count[a] = count.get(a, 0) + 1
                    needing.setdefault(a, []).append((i, r))
        placed: set = set()
        while count:
            best = max(count, key=lambda a: count[a] * weight.get(a, 1.0001))
            group = [(i, r) for i, r in needing[best] if i not in placed]
            for i, r in group:
                placed.add(i)
                for a in r:
                    count[a] -= 1
                    if not count[a]:
                        del count[a]
            node[best] = build([i for i, _ in group], used | {best})
        return node
    return build(range(len(keys)), frozenset())


def atom_shares(states: list) -> dict:
    """atom -> the share of `states` (ints) in which it holds (atoms that never hold are
    left out). Walks each state's set bits only: a state of thousands of atoms has few."""
    count: dict = {}
    for s in states:
        while s:
            low = s & -s
            atom = low.bit_length() - 1
            count[atom] = count.get(atom, 0) + 1
            s ^= low
    return {a: c / len(states) for a, c in count.items()}


def _flatten(node) -> list:
    """The conjuncts of an IR condition."""
    if isinstance(node, ir.BoolOp) and node.op == "and":
        return [c for item in node.items for c in _flatten(item)]
    if node == ir.TRUE:
        return []
    return [node]


def _atoms(node) -> list:
    """The state variables an IR condition reads."""
    if isinstance(node, ir.Var):
        return [node.var]
    if isinstance(node, ir.Not):
        return _atoms(node.operand)
    if isinstance(node, ir.BoolOp):
        return [v for item in node.items for v in _atoms(item)]
    return []


class BitEmitter:
    def __init__(self, bit_of: dict):
        self.bit_of = bit_of     # StateVar -> atom number

    def mask(self, variables) -> int:
        m = 0
        for v in variables:
            m |= 1 << self.bit_of[v]
        return m

    def cond(self, node, v: str = "s") -> str:
        """A Python expression, true when the IR condition holds in the state named `v`."""
        conj = _flatten(node)
        if len(conj) != 1 or isinstance(node, ir.BoolOp) and node.op == "and":
            return self.conjunction(conj, v)
        if isinstance(node, ir.Var):
            return f"{v} & {self.mask([node.var]):#x}"
        if isinstance(node, ir.Not):
            return f"not ({self.cond(node.operand, v)})"
        if isinstance(node, ir.BoolOp):
            return "(" + " or ".join(f"({self.cond(c, v)})" for c in node.items) + ")" if node.items else "False"
        if isinstance(node, ir.Const):
            return "True" if node.value else "False"
        raise TypeError(f"unexpected condition {type(node).__name__}")

    def conjunction(self, conj: list, v: str = "s") -> str:
        """`conj` (IR conditions) all true: positive atoms as one mask, negated ones as another."""
        pos = [c.var for c in conj if isinstance(c, ir.Var)]
        neg = [c.operand.var for c in conj if isinstance(c, ir.Not) and isinstance(c.operand, ir.Var)]
        rest = [c for c in conj if not isinstance(c, ir.Var) and not (isinstance(c, ir.Not)
                                                                      and isinstance(c.operand, ir.Var))]
        parts = []
        if pos:
            m = self.mask(pos)
            parts.append(f"{v} & {m:#x} == {m:#x}" if len(pos) > 1 else f"{v} & {m:#x}")
        if neg:
            parts.append(f"not {v} & {self.mask(neg):#x}")
        parts += [f"({self.cond(c, v)})" for c in rest]
        return " and ".join(parts) if parts else "True"

    def writes(self, effects) -> int:
        """The mask of every atom `effects` may set or clear."""
        return self.mask(w.var for e in effects for w in ((*e.then, *e.orelse) if isinstance(e, ir.When) else (e,)))

    def effects(self, effects) -> tuple[int, int, list]:
        """(delete mask, add mask, [(condition, delete mask, add mask)]) of an action's
        effects: unconditional `SetVar`s and `When`s of `SetVar`s."""
        dels = adds = 0
        conditional = []
        for e in effects:
            if isinstance(e, ir.When):
                d = a = 0
                for w in e.then:
                    if w.value.value:
                        a |= 1 << self.bit_of[w.var]
                    else:
                        d |= 1 << self.bit_of[w.var]
                conditional.append((self.cond(e.cond), d, a))
            elif e.value.value:
                adds |= 1 << self.bit_of[e.var]
            else:
                dels |= 1 << self.bit_of[e.var]
        return dels, adds, conditional

    def successors_source(self, actions: list, prob: dict | None = None, goal=None, costs: list | None = None) -> str:
        """`successors(s)`: [(action, next state)]; or, given the IR `goal`, a layer
        expander `expand(states, seen, outs)` (Model.search_layers, one group): for each of
        `states` (none a goal), each next state not yet a key of `seen` is stored there
        with its parent and appended to `outs[0]`; it returns how many next states there
        were, or at once the complement of that count when a new one is a goal (the last
        of `outs[0]`). The goal is tested inline, only after actions that write an atom
        it reads: any other action leaves it as false as in the parent. Or, given the
        actions' `costs`, `expand_costs(states, g, nodes, outs)` for a search by cost
        (solvers/uniform_cost.py): `states` all cost g; a next state t made by an action
        of the r-th smallest distinct cost c is stored as `nodes[t] = (g + c, s)` and
        appended to `outs[r]` unless `nodes` has it at g + c or less; it returns how many
        next states there were. With `prob` (atom_shares of sampled states), the tree's
        tests are chosen by what they prune (_tree_by_pruning)."""
        keys = [[self.bit_of[c.var] for c in a.pre if isinstance(c, ir.Var)] for a in actions]
        root = _tree_by_frequency(keys) if prob is None else _tree_by_pruning(keys, prob)
        expand = goal is not None or costs is not None
        if costs is not None:
            rank = {c: r for r, c in enumerate(sorted(set(costs)))}
            lines = ["def expand_costs(states, g, nodes, outs):", "    get = nodes.get", "    k = 0"]
            for c, r in rank.items():
                lines += [f"    o{r} = outs[{r}].append", f"    g{r} = g + {int(c)}"]
            lines.append("    for s in states:")
        elif expand:
            lines = ["def expand(states, seen, outs):", "    out = outs[0]", "    add = out.append", "    k = 0",
                     "    for s in states:"]
            goal_test = self.cond(goal, "t")
            goal_mask = self.mask(_atoms(goal))
        else:
            lines = ["def successors(s):", "    out = []", "    add = out.append"]

        def put(i, nxt, indent):
            if not expand:
                lines.append(f"{indent}add(({i}, {nxt}))")
                return
            if costs is not None:
                r = rank[costs[i]]
                lines.extend([f"{indent}k += 1", f"{indent}t = {nxt}", f"{indent}old = get(t)",
                              f"{indent}if old is None or old[0] > g{r}:",
                              f"{indent}    nodes[t] = (g{r}, s)", f"{indent}    o{r}(t)"])
                return
            lines.extend([f"{indent}k += 1", f"{indent}t = {nxt}", f"{indent}if t not in seen:",
                          f"{indent}    seen[t] = s", f"{indent}    add(t)"])
            if self.writes(actions[i].effects) & goal_mask:
                lines.extend([f"{indent}    if {goal_test}:", f"{indent}        return ~k"])

        def leaf(i, used, indent):
            a = actions[i]
            rest = [c for c in a.pre if not (isinstance(c, ir.Var) and self.bit_of[c.var] in used)]
            if rest:
                lines.append(f"{indent}if {self.conjunction(rest)}:")
                indent += "    "
            dels, adds, conditional = self.effects(a.effects)
            if not conditional:
                nxt = "s" + (f" & {~dels:#x}" if dels else "") + (f" | {adds:#x}" if adds else "")
                put(i, nxt, indent)
                return
            lines.append(f"{indent}d = {dels:#x}")
            lines.append(f"{indent}a = {adds:#x}")
            for cond, d, ad in conditional:
                lines.append(f"{indent}if {cond}:")
                lines.append(f"{indent}    d |= {d:#x}")
                lines.append(f"{indent}    a |= {ad:#x}")
            put(i, "s & ~d | a", indent)

        def single(node):
            """The one action in `node`'s subtree, or None if it holds more."""
            found = None
            for atom, child in node.items():
                for i in (child if atom is None else [single(child)]):
                    if i is None or found is not None:
                        return None
                    found = i
            return found

        def emit(node, used, indent):
            for i in node.get(None, ()):
                leaf(i, used, indent)
            children = sorted((atom, child) for atom, child in node.items() if atom is not None)
            split(children, used, indent)

        def split(children, used, indent):
            """Many children: test groups of them with one mask first (recursively, FAN
            groups a level), so a state skips every group none of whose atoms holds: a
            wide node, e.g. one child per location of a truck, has few true atoms."""
            if len(children) <= FAN or len(indent) >= 4 * MAX_NESTING:
                for atom, child in children:
                    only = single(child)
                    if only is not None:      # one action below: all its atoms in one mask test
                        leaf(only, used, indent)
                        continue
                    lines.append(f"{indent}if s & {1 << atom:#x}:")
                    emit(child, used | {atom}, indent + "    ")
                return
            size = -(-len(children) // FAN)
            for k in range(0, len(children), size):
                group = children[k:k + size]
                if len(group) == 1:
                    split(group, used, indent)
                    continue
                lines.append(f"{indent}if s & {sum(1 << atom for atom, _ in group):#x}:")
                split(group, used, indent + "    ")

        emit(root, frozenset(), "        " if expand else "    ")
        if lines[-1] == "    for s in states:":
            lines.append("        pass")     # no actions
        lines.append("    return k" if expand else "    return out")
        return "\n".join(lines)

    def predicate_source(self, name: str, node) -> str:
        return f"def {name}(s):\n    return bool({self.cond(node)})"
