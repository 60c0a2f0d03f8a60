"""The reward-function grounding layer (issue 6): natural-language commands -> goal expressions.

Learned from (command, demonstration) pairs as in MacGlashan et al. (2015): candidate tasks
come from the compiled domain (tasks.py, predicates.py), a demonstration's task is inferred
from its states (infer.py), and IBM Model 2 trained with EM aligns words with task tokens
(translation.py). Demonstrations are read in the format the web viewer and the Minecraft
recorder share (bcc/demonstration.py); dataset.py is the user's SQLite dataset; corpus.py the shipped
corpus; interpret.py turns a command into a task and a plan; its commands are in cli/grounding.py.
"""
