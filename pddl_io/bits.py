"""Python source for an imported task (ground.py), with a state as one int: bit i is atom i.

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

The input is the ground task itself (formulas over atom numbers: an int, ("not", f),
("and", fs), ("or", fs), ("true",), ("false",)), not bcc's IR: importing the IR's
classes cost about a tenth of a small problem's whole run.
"""
from __future__ import annotations

from collections import Counter

TRUE = ("true",)

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


def _flatten(f) -> list:
    """The conjuncts of a ground formula."""
    if isinstance(f, tuple) and f[0] == "and":
        return [c for item in f[1] for c in _flatten(item)]
    if f == TRUE:
        return []
    return [f]


def _atoms(f) -> list:
    """The atoms a ground formula reads."""
    if isinstance(f, int):
        return [f]
    if f[0] == "not":
        return _atoms(f[1])
    if f[0] in ("and", "or"):
        return [a for g in f[1] for a in _atoms(g)]
    return []


def _negated_atom(c) -> bool:
    return isinstance(c, tuple) and c[0] == "not" and isinstance(c[1], int)


def mask(atoms) -> int:
    m = 0
    for a in atoms:
        m |= 1 << a
    return m


class BitEmitter:
    def cond(self, f, v: str = "s") -> str:
        """A Python expression, true when the ground formula `f` holds in the state named `v`."""
        if isinstance(f, int):
            return f"{v} & {1 << f:#x}"
        kind = f[0]
        if kind == "and":
            return self.conjunction(_flatten(f), v)
        if kind == "not":
            return f"not ({self.cond(f[1], v)})"
        if kind == "or":
            return "(" + " or ".join(f"({self.cond(g, v)})" for g in f[1]) + ")" if f[1] else "False"
        if kind in ("true", "false"):
            return "True" if kind == "true" else "False"
        raise TypeError(f"unexpected formula {kind!r}")

    def conjunction(self, conj: list, v: str = "s") -> str:
        """`conj` (ground formulas) all true: positive atoms as one mask, negated ones as another."""
        pos = [c for c in conj if isinstance(c, int)]
        neg = [c[1] for c in conj if _negated_atom(c)]
        rest = [c for c in conj if not isinstance(c, int) and not _negated_atom(c)]
        parts = []
        if pos:
            m = mask(pos)
            parts.append(f"{v} & {m:#x} == {m:#x}" if len(pos) > 1 else f"{v} & {m:#x}")
        if neg:
            parts.append(f"not {v} & {mask(neg):#x}")
        parts += [f"({self.cond(c, v)})" for c in rest]
        return " and ".join(parts) if parts else "True"

    def positive_mask(self, action) -> int:
        """The atoms an action's precondition needs true (its top-level conjunction's)."""
        return mask(c for c in _flatten(action.pre) if isinstance(c, int))

    def tree_order(self, actions: list) -> list:
        """The actions in the order `successors` (by frequency) lists their next states."""
        root = _tree_by_frequency([[c for c in _flatten(a.pre) if isinstance(c, int)] for a in actions])
        out: list = []

        def walk(node):
            out.extend(node.get(None, ()))
            for atom in sorted(a for a in node if a is not None):
                walk(node[atom])
        walk(root)
        return out

    def writes(self, effects) -> int:
        """The mask of every atom `effects` (a ground action's) may set or clear."""
        return mask(atom for _, atom, _ in effects)

    def effects(self, effects) -> tuple[int, int, list]:
        """(delete mask, add mask, [(condition, delete mask, add mask)]) of a ground
        action's effects [(condition, atom, add?)]: an atom both deleted and added holds."""
        dels = adds = 0
        conditional: list = []     # [[condition, delete mask, add mask]], one per distinct condition
        for cond, atom, add in effects:
            if cond == TRUE:
                if add:
                    adds |= 1 << atom
                else:
                    dels |= 1 << atom
                continue
            entry = next((e for e in conditional if e[0] == cond), None)
            if entry is None:
                entry = [cond, 0, 0]
                conditional.append(entry)
            entry[2 if add else 1] |= 1 << atom
        return dels, adds, [(self.cond(c), d, a) for c, d, a in conditional]

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
        conjs = [_flatten(a.pre) for a in actions]
        keys = [[c for c in conj if isinstance(c, int)] for conj in conjs]
        root = _tree_by_frequency(keys) if prob is None else _tree_by_pruning(keys, prob)
        expand = goal is not None or costs is not None
        tree = _TreeSource(self, actions, conjs, goal, costs)
        tree.emit(root, frozenset(), "        " if expand else "    ")
        lines = tree.lines
        if lines[-1] == "    for s in states:":
            lines.append("        pass")     # no actions
        lines.append("    return k" if expand else "    return out")
        return "\n".join(lines)

    def predicate_source(self, name: str, node) -> str:
        return f"def {name}(s):\n    return bool({self.cond(node)})"


class _TreeSource:
    """The lines of `successors_source`: its function's head, then the decision tree
    (`emit`) of nested `if`s over atoms, one leaf per action that writes its next state
    (`put`) the way the function asks: listed, stored for a layer (with the goal test),
    or stored by cost."""

    def __init__(self, em: BitEmitter, actions: list, conjs: list, goal, costs: list | None):
        self.em, self.actions, self.conjs, self.costs = em, actions, conjs, costs
        self.expand = goal is not None or costs is not None
        if costs is not None:
            self.rank = rank = {c: r for r, c in enumerate(sorted(set(costs)))}
            lines = ["def expand_costs(states, g, nodes, outs):", "    get = nodes.get", "    k = 0"]
            for c, r in rank.items():
                lines += [f"    o{r} = outs[{r}].append", f"    g{r} = g + {int(c)}"]
            lines.append("    for s in states:")
        elif self.expand:
            lines = ["def expand(states, seen, outs):", "    out = outs[0]", "    add = out.append", "    k = 0",
                     "    for s in states:"]
            self.goal_test = em.cond(goal, "t")
            self.goal_mask = mask(_atoms(goal))
        else:
            lines = ["def successors(s):", "    out = []", "    add = out.append"]
        self.lines = lines

    def put(self, i, nxt, indent):
        lines = self.lines
        if not self.expand:
            lines.append(f"{indent}add(({i}, {nxt}))")
            return
        if self.costs is not None:
            r = self.rank[self.costs[i]]
            lines.extend([f"{indent}k += 1", f"{indent}t = {nxt}", f"{indent}old = get(t)",
                          f"{indent}if old is None or old[0] > g{r}:",
                          f"{indent}    nodes[t] = (g{r}, s)", f"{indent}    o{r}(t)"])
            return
        lines.extend([f"{indent}k += 1", f"{indent}t = {nxt}", f"{indent}if t not in seen:",
                      f"{indent}    seen[t] = s", f"{indent}    add(t)"])
        if self.em.writes(self.actions[i].effects) & self.goal_mask:
            lines.extend([f"{indent}    if {self.goal_test}:", f"{indent}        return ~k"])

    def leaf(self, i, used, indent):
        lines, em = self.lines, self.em
        a = self.actions[i]
        rest = [c for c in self.conjs[i] if not (isinstance(c, int) and c in used)]
        if rest:
            lines.append(f"{indent}if {em.conjunction(rest)}:")
            indent += "    "
        dels, adds, conditional = em.effects(a.effects)
        if not conditional:
            nxt = "s" + (f" & {~dels:#x}" if dels else "") + (f" | {adds:#x}" if adds else "")
            self.put(i, nxt, indent)
            return
        lines.append(f"{indent}d = {dels:#x}")
        lines.append(f"{indent}a = {adds:#x}")
        for cond, d, ad in conditional:
            lines.append(f"{indent}if {cond}:")
            lines.append(f"{indent}    d |= {d:#x}")
            lines.append(f"{indent}    a |= {ad:#x}")
        self.put(i, "s & ~d | a", indent)

    def emit(self, node, used, indent):
        for i in node.get(None, ()):
            self.leaf(i, used, indent)
        children = sorted((atom, child) for atom, child in node.items() if atom is not None)
        self.split(children, used, indent)

    def split(self, children, used, indent):
        """Many children: test groups of them with one mask first (recursively, FAN
        groups a level), so a state skips every group none of whose atoms holds: a
        wide node, e.g. one child per location of a truck, has few true atoms."""
        lines = self.lines
        if len(children) <= FAN or len(indent) >= 4 * MAX_NESTING:
            for atom, child in children:
                only = _single(child)
                if only is not None:      # one action below: all its atoms in one mask test
                    self.leaf(only, used, indent)
                    continue
                lines.append(f"{indent}if s & {1 << atom:#x}:")
                self.emit(child, used | {atom}, indent + "    ")
            return
        size = -(-len(children) // FAN)
        for k in range(0, len(children), size):
            group = children[k:k + size]
            if len(group) == 1:
                self.split(group, used, indent)
                continue
            lines.append(f"{indent}if s & {sum(1 << atom for atom, _ in group):#x}:")
            self.split(group, used, indent + "    ")


def _single(node):
    """The one action in `node`'s subtree, or None if it holds more."""
    found = None
    for atom, child in node.items():
        for i in (child if atom is None else [_single(child)]):
            if i is None or found is not None:
                return None
            found = i
    return found
