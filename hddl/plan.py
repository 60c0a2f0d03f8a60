"""The IPC 2020 HTN plan format: the actions, then the decomposition tree.

    ==>
    0 drive t1 a b
    1 drive t1 b c
    root 2
    2 get-to t1 c -> m-via 0 3
    3 get-to t1 c -> m-drive 1
    <==

Actions are numbered 0..n-1 in plan order; each compound task is `id task args ->
method subtask-ids` (in the method's order); `root` lists the problem's network. This is
what the competition's verifier (pandaPIparser -V) reads.
"""
from __future__ import annotations


def ipc_plan_text(plan: list, decomposition: dict) -> str:
    """The IPC text of a plan ("(name a b)" per action) and its decomposition tree."""
    lines = ["==>"]
    for i, action in enumerate(plan):
        lines.append(f"{i} {action.strip('()')}")
    lines.append("root " + " ".join(map(str, decomposition["root"])))
    for t in decomposition["tasks"]:
        lines.append(f"{t['id']} {t['task']} -> {t['method']} " + " ".join(map(str, t["subtasks"])))
    lines.append("<==")
    return "\n".join(line.rstrip() for line in lines) + "\n"
