"""MinePlanner's 15 tasks and 3 levels, as its repository names them: the one list both
MinePlanner benches (native and through PDDL) walk."""

TASKS = ["Bridge", "Build_Cabin", "Build_Cross", "Build_Shape", "Build_Wall", "Build_Well", "Climb_Place",
         "Collect_Build_Shape", "Cut_Tree", "Gather_Multiple_Wood", "Gather_Wood", "Move_to_Location",
         "Pickup_Diamond", "Pickup_and_Place", "Place_Wood"]
LEVELS = ["Easy", "Medium", "Hard"]
