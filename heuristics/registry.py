"""Every heuristic by name: `HEURISTICS[name](model)` returns h(state) -> number."""
from __future__ import annotations

from .counting import counting
from .patterns import pdb
from .position import blind, manhattan
from .relaxed import relaxed_heuristic

# Never above the true cost, so 0 on every goal state: a state they rate above 0 is no goal
ADMISSIBLE = frozenset({"blind", "manhattan", "pdb", "hmax", "lmcut", "counting"})
HEURISTICS = {"pdb": pdb, "manhattan": manhattan, "blind": blind,
              "hmax": relaxed_heuristic("hmax"), "hadd": relaxed_heuristic("hadd"), "hff": relaxed_heuristic("hff"),
              "lmcut": relaxed_heuristic("lmcut"), "counting": counting}
