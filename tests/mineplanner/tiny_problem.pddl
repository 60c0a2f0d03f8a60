;; The world of tests/mineplanner/tiny_domain.pddl: a bedrock floor x = 0..5, a stone at
;; x = 1 in front of the agent, a cobblestone item at x = 2.
(define (problem tiny_problem)
	(:domain tiny)
(:objects
	steve - agent
	bedrock0 bedrock1 bedrock2 bedrock3 bedrock4 bedrock5 - bedrock
	stone-block0 stone-block1 - stone-block
	cobblestone-block0 - cobblestone-block
	cobblestone0 - cobblestone
	stone0 - stone
	position0 position1 position2 position3 position4 position5 position6 - position
	count0 count1 count2 count3 - count
)
(:init
	(are-seq position0 position1)
	(are-seq position1 position2)
	(are-seq position2 position3)
	(are-seq position3 position4)
	(are-seq position4 position5)
	(are-seq position5 position6)
	(are-seq count0 count1)
	(are-seq count1 count2)
	(are-seq count2 count3)
	(at-x steve position0) (at-y steve position1) (at-z steve position0)
	(agent-alive steve)
	(agent-has-n-stone steve count0)
	(agent-has-n-cobblestone steve count0)
	(at-x bedrock0 position0) (at-y bedrock0 position0) (at-z bedrock0 position0) (block-present bedrock0)
	(at-x bedrock1 position1) (at-y bedrock1 position0) (at-z bedrock1 position0) (block-present bedrock1)
	(at-x bedrock2 position2) (at-y bedrock2 position0) (at-z bedrock2 position0) (block-present bedrock2)
	(at-x bedrock3 position3) (at-y bedrock3 position0) (at-z bedrock3 position0) (block-present bedrock3)
	(at-x bedrock4 position4) (at-y bedrock4 position0) (at-z bedrock4 position0) (block-present bedrock4)
	(at-x bedrock5 position5) (at-y bedrock5 position0) (at-z bedrock5 position0) (block-present bedrock5)
	(at-x stone-block0 position1) (at-y stone-block0 position1) (at-z stone-block0 position0) (block-present stone-block0)
	(at-x cobblestone0 position2) (at-y cobblestone0 position1) (at-z cobblestone0 position0) (item-present cobblestone0)
)
(:goal (and (goal-achieved steve)))
)
