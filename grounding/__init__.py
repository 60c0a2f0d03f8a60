"""The reward-function grounding layer: natural-language commands -> goal expressions,
learned from (command, demonstration) pairs with IBM Model 2 (issue 6)."""
