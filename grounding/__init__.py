"""The reward-function grounding layer (issue 6): natural-language commands -> goal expressions.

Learned from (command, demonstration) pairs as in MacGlashan et al. (2015): candidate tasks
come from the compiled domain (tasks.py, predicates.py), a demonstration's task is inferred
from its states (infer.py), and IBM Model 2 trained with EM aligns words with task tokens
(translation.py). demonstration.py is the demonstration format shared with the web viewer
and the Minecraft recorder; dataset.py the user's SQLite dataset; corpus.py the shipped
corpus; interpret.py turns a command into a task and a plan; its commands are in cli/grounding.py.
"""
