begin_version
3
end_version
begin_metric
0
end_metric
104
begin_variable
var0
-1
2
Atom agent-verticaldirection(n0)
Atom agent-verticaldirection(n1)
end_variable
begin_variable
var1
-1
9
Atom agent-selecteditem(n0)
Atom agent-selecteditem(n1)
Atom agent-selecteditem(n2)
Atom agent-selecteditem(n3)
Atom agent-selecteditem(n4)
Atom agent-selecteditem(n5)
Atom agent-selecteditem(n6)
Atom agent-selecteditem(n7)
Atom agent-selecteditem(n8)
end_variable
begin_variable
var2
-1
4
Atom agent-rotationaldirection(n0)
Atom agent-rotationaldirection(n1)
Atom agent-rotationaldirection(n2)
Atom agent-rotationaldirection(n3)
end_variable
begin_variable
var3
-1
2
Atom cell(x1, y1, z1, air)
Atom cell(x1, y1, z1, burlap-stone)
end_variable
begin_variable
var4
-1
2
Atom cell(x1, y1, z13, air)
Atom cell(x1, y1, z13, burlap-stone)
end_variable
begin_variable
var5
-1
2
Atom cell(x13, y1, z1, air)
Atom cell(x13, y1, z1, burlap-stone)
end_variable
begin_variable
var6
-1
2
Atom cell(x13, y1, z13, air)
Atom cell(x13, y1, z13, burlap-stone)
end_variable
begin_variable
var7
-1
2
Atom cell(x1, y1, z11, air)
Atom cell(x1, y1, z11, burlap-stone)
end_variable
begin_variable
var8
-1
2
Atom cell(x1, y1, z12, air)
Atom cell(x1, y1, z12, burlap-stone)
end_variable
begin_variable
var9
-1
2
Atom cell(x1, y1, z3, air)
Atom cell(x1, y1, z3, burlap-stone)
end_variable
begin_variable
var10
-1
2
Atom cell(x1, y1, z4, air)
Atom cell(x1, y1, z4, burlap-stone)
end_variable
begin_variable
var11
-1
2
Atom cell(x1, y1, z5, air)
Atom cell(x1, y1, z5, burlap-stone)
end_variable
begin_variable
var12
-1
2
Atom cell(x1, y1, z6, air)
Atom cell(x1, y1, z6, burlap-stone)
end_variable
begin_variable
var13
-1
2
Atom cell(x1, y1, z7, air)
Atom cell(x1, y1, z7, burlap-stone)
end_variable
begin_variable
var14
-1
2
Atom cell(x1, y1, z8, air)
Atom cell(x1, y1, z8, burlap-stone)
end_variable
begin_variable
var15
-1
2
Atom cell(x1, y1, z9, air)
Atom cell(x1, y1, z9, burlap-stone)
end_variable
begin_variable
var16
-1
2
Atom cell(x10, y1, z13, air)
Atom cell(x10, y1, z13, burlap-stone)
end_variable
begin_variable
var17
-1
2
Atom cell(x11, y1, z1, air)
Atom cell(x11, y1, z1, burlap-stone)
end_variable
begin_variable
var18
-1
2
Atom cell(x11, y1, z13, air)
Atom cell(x11, y1, z13, burlap-stone)
end_variable
begin_variable
var19
-1
2
Atom cell(x12, y1, z1, air)
Atom cell(x12, y1, z1, burlap-stone)
end_variable
begin_variable
var20
-1
2
Atom cell(x12, y1, z13, air)
Atom cell(x12, y1, z13, burlap-stone)
end_variable
begin_variable
var21
-1
2
Atom cell(x13, y1, z10, air)
Atom cell(x13, y1, z10, burlap-stone)
end_variable
begin_variable
var22
-1
2
Atom cell(x13, y1, z11, air)
Atom cell(x13, y1, z11, burlap-stone)
end_variable
begin_variable
var23
-1
2
Atom cell(x13, y1, z2, air)
Atom cell(x13, y1, z2, burlap-stone)
end_variable
begin_variable
var24
-1
2
Atom cell(x13, y1, z3, air)
Atom cell(x13, y1, z3, burlap-stone)
end_variable
begin_variable
var25
-1
2
Atom cell(x13, y1, z5, air)
Atom cell(x13, y1, z5, burlap-stone)
end_variable
begin_variable
var26
-1
2
Atom cell(x13, y1, z6, air)
Atom cell(x13, y1, z6, burlap-stone)
end_variable
begin_variable
var27
-1
2
Atom cell(x13, y1, z7, air)
Atom cell(x13, y1, z7, burlap-stone)
end_variable
begin_variable
var28
-1
2
Atom cell(x13, y1, z8, air)
Atom cell(x13, y1, z8, burlap-stone)
end_variable
begin_variable
var29
-1
2
Atom cell(x13, y1, z9, air)
Atom cell(x13, y1, z9, burlap-stone)
end_variable
begin_variable
var30
-1
2
Atom cell(x2, y1, z1, air)
Atom cell(x2, y1, z1, burlap-stone)
end_variable
begin_variable
var31
-1
2
Atom cell(x2, y1, z13, air)
Atom cell(x2, y1, z13, burlap-stone)
end_variable
begin_variable
var32
-1
2
Atom cell(x3, y1, z1, air)
Atom cell(x3, y1, z1, burlap-stone)
end_variable
begin_variable
var33
-1
2
Atom cell(x3, y1, z13, air)
Atom cell(x3, y1, z13, burlap-stone)
end_variable
begin_variable
var34
-1
2
Atom cell(x4, y1, z1, air)
Atom cell(x4, y1, z1, burlap-stone)
end_variable
begin_variable
var35
-1
2
Atom cell(x5, y1, z1, air)
Atom cell(x5, y1, z1, burlap-stone)
end_variable
begin_variable
var36
-1
2
Atom cell(x5, y1, z13, air)
Atom cell(x5, y1, z13, burlap-stone)
end_variable
begin_variable
var37
-1
2
Atom cell(x6, y1, z13, air)
Atom cell(x6, y1, z13, burlap-stone)
end_variable
begin_variable
var38
-1
2
Atom cell(x7, y1, z1, air)
Atom cell(x7, y1, z1, burlap-stone)
end_variable
begin_variable
var39
-1
2
Atom cell(x7, y1, z13, air)
Atom cell(x7, y1, z13, burlap-stone)
end_variable
begin_variable
var40
-1
2
Atom cell(x8, y1, z1, air)
Atom cell(x8, y1, z1, burlap-stone)
end_variable
begin_variable
var41
-1
2
Atom cell(x8, y1, z13, air)
Atom cell(x8, y1, z13, burlap-stone)
end_variable
begin_variable
var42
-1
2
Atom cell(x9, y1, z1, air)
Atom cell(x9, y1, z1, burlap-stone)
end_variable
begin_variable
var43
-1
2
Atom cell(x9, y1, z13, air)
Atom cell(x9, y1, z13, burlap-stone)
end_variable
begin_variable
var44
-1
2
Atom cell(x10, y1, z11, air)
Atom cell(x10, y1, z11, burlap-stone)
end_variable
begin_variable
var45
-1
2
Atom cell(x10, y1, z3, air)
Atom cell(x10, y1, z3, burlap-stone)
end_variable
begin_variable
var46
-1
2
Atom cell(x10, y1, z5, air)
Atom cell(x10, y1, z5, burlap-stone)
end_variable
begin_variable
var47
-1
2
Atom cell(x10, y1, z9, air)
Atom cell(x10, y1, z9, burlap-stone)
end_variable
begin_variable
var48
-1
2
Atom cell(x11, y1, z11, air)
Atom cell(x11, y1, z11, burlap-stone)
end_variable
begin_variable
var49
-1
2
Atom cell(x11, y1, z2, air)
Atom cell(x11, y1, z2, burlap-stone)
end_variable
begin_variable
var50
-1
2
Atom cell(x11, y1, z3, air)
Atom cell(x11, y1, z3, burlap-stone)
end_variable
begin_variable
var51
-1
2
Atom cell(x11, y1, z5, air)
Atom cell(x11, y1, z5, burlap-stone)
end_variable
begin_variable
var52
-1
2
Atom cell(x11, y1, z7, air)
Atom cell(x11, y1, z7, burlap-stone)
end_variable
begin_variable
var53
-1
2
Atom cell(x11, y1, z8, air)
Atom cell(x11, y1, z8, burlap-stone)
end_variable
begin_variable
var54
-1
2
Atom cell(x11, y1, z9, air)
Atom cell(x11, y1, z9, burlap-stone)
end_variable
begin_variable
var55
-1
2
Atom cell(x12, y1, z11, air)
Atom cell(x12, y1, z11, burlap-stone)
end_variable
begin_variable
var56
-1
2
Atom cell(x12, y1, z5, air)
Atom cell(x12, y1, z5, burlap-stone)
end_variable
begin_variable
var57
-1
2
Atom cell(x12, y1, z7, air)
Atom cell(x12, y1, z7, burlap-stone)
end_variable
begin_variable
var58
-1
2
Atom cell(x2, y1, z3, air)
Atom cell(x2, y1, z3, burlap-stone)
end_variable
begin_variable
var59
-1
2
Atom cell(x2, y1, z9, air)
Atom cell(x2, y1, z9, burlap-stone)
end_variable
begin_variable
var60
-1
2
Atom cell(x3, y1, z11, air)
Atom cell(x3, y1, z11, burlap-stone)
end_variable
begin_variable
var61
-1
2
Atom cell(x3, y1, z12, air)
Atom cell(x3, y1, z12, burlap-stone)
end_variable
begin_variable
var62
-1
2
Atom cell(x3, y1, z3, air)
Atom cell(x3, y1, z3, burlap-stone)
end_variable
begin_variable
var63
-1
2
Atom cell(x3, y1, z4, air)
Atom cell(x3, y1, z4, burlap-stone)
end_variable
begin_variable
var64
-1
2
Atom cell(x3, y1, z5, air)
Atom cell(x3, y1, z5, burlap-stone)
end_variable
begin_variable
var65
-1
2
Atom cell(x3, y1, z7, air)
Atom cell(x3, y1, z7, burlap-stone)
end_variable
begin_variable
var66
-1
2
Atom cell(x3, y1, z9, air)
Atom cell(x3, y1, z9, burlap-stone)
end_variable
begin_variable
var67
-1
2
Atom cell(x4, y1, z11, air)
Atom cell(x4, y1, z11, burlap-stone)
end_variable
begin_variable
var68
-1
2
Atom cell(x4, y1, z5, air)
Atom cell(x4, y1, z5, burlap-stone)
end_variable
begin_variable
var69
-1
2
Atom cell(x4, y1, z7, air)
Atom cell(x4, y1, z7, burlap-stone)
end_variable
begin_variable
var70
-1
2
Atom cell(x4, y1, z9, air)
Atom cell(x4, y1, z9, burlap-stone)
end_variable
begin_variable
var71
-1
2
Atom cell(x5, y1, z11, air)
Atom cell(x5, y1, z11, burlap-stone)
end_variable
begin_variable
var72
-1
2
Atom cell(x5, y1, z12, air)
Atom cell(x5, y1, z12, burlap-stone)
end_variable
begin_variable
var73
-1
2
Atom cell(x5, y1, z2, air)
Atom cell(x5, y1, z2, burlap-stone)
end_variable
begin_variable
var74
-1
2
Atom cell(x5, y1, z3, air)
Atom cell(x5, y1, z3, burlap-stone)
end_variable
begin_variable
var75
-1
2
Atom cell(x5, y1, z4, air)
Atom cell(x5, y1, z4, burlap-stone)
end_variable
begin_variable
var76
-1
2
Atom cell(x5, y1, z5, air)
Atom cell(x5, y1, z5, burlap-stone)
end_variable
begin_variable
var77
-1
2
Atom cell(x5, y1, z7, air)
Atom cell(x5, y1, z7, burlap-stone)
end_variable
begin_variable
var78
-1
2
Atom cell(x5, y1, z8, air)
Atom cell(x5, y1, z8, burlap-stone)
end_variable
begin_variable
var79
-1
2
Atom cell(x5, y1, z9, air)
Atom cell(x5, y1, z9, burlap-stone)
end_variable
begin_variable
var80
-1
2
Atom cell(x6, y1, z7, air)
Atom cell(x6, y1, z7, burlap-stone)
end_variable
begin_variable
var81
-1
2
Atom cell(x7, y1, z11, air)
Atom cell(x7, y1, z11, burlap-stone)
end_variable
begin_variable
var82
-1
2
Atom cell(x7, y1, z12, air)
Atom cell(x7, y1, z12, burlap-stone)
end_variable
begin_variable
var83
-1
2
Atom cell(x7, y1, z2, air)
Atom cell(x7, y1, z2, burlap-stone)
end_variable
begin_variable
var84
-1
2
Atom cell(x7, y1, z3, air)
Atom cell(x7, y1, z3, burlap-stone)
end_variable
begin_variable
var85
-1
2
Atom cell(x7, y1, z4, air)
Atom cell(x7, y1, z4, burlap-stone)
end_variable
begin_variable
var86
-1
2
Atom cell(x7, y1, z5, air)
Atom cell(x7, y1, z5, burlap-stone)
end_variable
begin_variable
var87
-1
2
Atom cell(x7, y1, z7, air)
Atom cell(x7, y1, z7, burlap-stone)
end_variable
begin_variable
var88
-1
2
Atom cell(x7, y1, z8, air)
Atom cell(x7, y1, z8, burlap-stone)
end_variable
begin_variable
var89
-1
2
Atom cell(x7, y1, z9, air)
Atom cell(x7, y1, z9, burlap-stone)
end_variable
begin_variable
var90
-1
2
Atom cell(x8, y1, z11, air)
Atom cell(x8, y1, z11, burlap-stone)
end_variable
begin_variable
var91
-1
2
Atom cell(x8, y1, z5, air)
Atom cell(x8, y1, z5, burlap-stone)
end_variable
begin_variable
var92
-1
2
Atom cell(x8, y1, z9, air)
Atom cell(x8, y1, z9, burlap-stone)
end_variable
begin_variable
var93
-1
2
Atom cell(x9, y1, z11, air)
Atom cell(x9, y1, z11, burlap-stone)
end_variable
begin_variable
var94
-1
2
Atom cell(x9, y1, z2, air)
Atom cell(x9, y1, z2, burlap-stone)
end_variable
begin_variable
var95
-1
2
Atom cell(x9, y1, z3, air)
Atom cell(x9, y1, z3, burlap-stone)
end_variable
begin_variable
var96
-1
2
Atom cell(x9, y1, z5, air)
Atom cell(x9, y1, z5, burlap-stone)
end_variable
begin_variable
var97
-1
2
Atom cell(x9, y1, z6, air)
Atom cell(x9, y1, z6, burlap-stone)
end_variable
begin_variable
var98
-1
2
Atom cell(x9, y1, z7, air)
Atom cell(x9, y1, z7, burlap-stone)
end_variable
begin_variable
var99
-1
2
Atom cell(x9, y1, z9, air)
Atom cell(x9, y1, z9, burlap-stone)
end_variable
begin_variable
var100
-1
2
Atom inventoryblock-1-blocktype(air)
Atom inventoryblock-1-blocktype(burlap-stone)
end_variable
begin_variable
var101
-1
3
Atom inventoryblock-1-count(n0)
Atom inventoryblock-1-count(n1)
Atom inventoryblock-1-count(n2)
end_variable
begin_variable
var102
-1
13
Atom agent-z(n1)
Atom agent-z(n10)
Atom agent-z(n11)
Atom agent-z(n12)
Atom agent-z(n13)
Atom agent-z(n2)
Atom agent-z(n3)
Atom agent-z(n4)
Atom agent-z(n5)
Atom agent-z(n6)
Atom agent-z(n7)
Atom agent-z(n8)
Atom agent-z(n9)
end_variable
begin_variable
var103
-1
13
Atom agent-x(n1)
Atom agent-x(n10)
Atom agent-x(n11)
Atom agent-x(n12)
Atom agent-x(n13)
Atom agent-x(n2)
Atom agent-x(n3)
Atom agent-x(n4)
Atom agent-x(n5)
Atom agent-x(n6)
Atom agent-x(n7)
Atom agent-x(n8)
Atom agent-x(n9)
end_variable
0
begin_state
0
0
2
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
1
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
1
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
end_state
begin_goal
2
102 6
103 4
end_goal
2077
begin_operator
change_item__0 
0
1
0 1 0 1
1
end_operator
begin_operator
change_item__1 
0
1
0 1 1 2
1
end_operator
begin_operator
change_item__2 
0
1
0 1 2 3
1
end_operator
begin_operator
change_item__3 
0
1
0 1 3 4
1
end_operator
begin_operator
change_item__4 
0
1
0 1 4 5
1
end_operator
begin_operator
change_item__5 
0
1
0 1 5 6
1
end_operator
begin_operator
change_item__6 
0
1
0 1 6 7
1
end_operator
begin_operator
change_item__7 
0
1
0 1 7 8
1
end_operator
begin_operator
change_item__8 
0
1
0 1 8 0
1
end_operator
begin_operator
destroy_block__0 
5
2 0
1 0
0 1
103 0
102 5
3
0 9 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__1 
6
2 0
1 0
0 1
103 0
102 5
100 1
2
0 9 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__10 
6
2 0
1 0
0 1
103 0
102 8
100 1
2
0 12 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__100 
6
2 0
1 0
0 1
103 8
102 2
100 1
2
0 72 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__1000 
6
2 3
1 0
0 1
103 3
102 5
100 1
2
0 23 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__1001 
6
2 3
1 0
0 1
103 3
102 5
100 1
2
0 23 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__1002 
5
2 3
1 0
0 1
103 3
102 6
3
0 24 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__1003 
6
2 3
1 0
0 1
103 3
102 6
100 1
2
0 24 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__1004 
6
2 3
1 0
0 1
103 3
102 6
100 1
2
0 24 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__1005 
5
2 3
1 0
0 1
103 3
102 8
3
0 25 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__1006 
6
2 3
1 0
0 1
103 3
102 8
100 1
2
0 25 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__1007 
6
2 3
1 0
0 1
103 3
102 8
100 1
2
0 25 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__1008 
5
2 3
1 0
0 1
103 3
102 9
3
0 26 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__1009 
6
2 3
1 0
0 1
103 3
102 9
100 1
2
0 26 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__101 
6
2 0
1 0
0 1
103 8
102 2
100 1
2
0 72 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__1010 
6
2 3
1 0
0 1
103 3
102 9
100 1
2
0 26 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__1011 
5
2 3
1 0
0 1
103 3
102 10
3
0 27 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__1012 
6
2 3
1 0
0 1
103 3
102 10
100 1
2
0 27 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__1013 
6
2 3
1 0
0 1
103 3
102 10
100 1
2
0 27 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__1014 
5
2 3
1 0
0 1
103 3
102 11
3
0 28 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__1015 
6
2 3
1 0
0 1
103 3
102 11
100 1
2
0 28 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__1016 
6
2 3
1 0
0 1
103 3
102 11
100 1
2
0 28 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__1017 
5
2 3
1 0
0 1
103 3
102 12
3
0 29 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__1018 
6
2 3
1 0
0 1
103 3
102 12
100 1
2
0 29 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__1019 
6
2 3
1 0
0 1
103 3
102 12
100 1
2
0 29 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__102 
5
2 0
1 0
0 1
103 8
102 3
3
0 36 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__1020 
5
2 3
1 0
0 1
103 3
102 1
3
0 21 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__1021 
6
2 3
1 0
0 1
103 3
102 1
100 1
2
0 21 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__1022 
6
2 3
1 0
0 1
103 3
102 1
100 1
2
0 21 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__1023 
5
2 3
1 0
0 1
103 3
102 2
3
0 22 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__1024 
6
2 3
1 0
0 1
103 3
102 2
100 1
2
0 22 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__1025 
6
2 3
1 0
0 1
103 3
102 2
100 1
2
0 22 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__1026 
5
2 3
1 0
0 1
103 3
102 4
3
0 6 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__1027 
6
2 3
1 0
0 1
103 3
102 4
100 1
2
0 6 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__1028 
6
2 3
1 0
0 1
103 3
102 4
100 1
2
0 6 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__103 
6
2 0
1 0
0 1
103 8
102 3
100 1
2
0 36 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__104 
6
2 0
1 0
0 1
103 8
102 3
100 1
2
0 36 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__105 
5
2 0
1 0
0 1
103 9
102 9
3
0 80 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__106 
6
2 0
1 0
0 1
103 9
102 9
100 1
2
0 80 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__107 
6
2 0
1 0
0 1
103 9
102 9
100 1
2
0 80 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__108 
5
2 0
1 0
0 1
103 9
102 3
3
0 37 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__109 
6
2 0
1 0
0 1
103 9
102 3
100 1
2
0 37 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__11 
6
2 0
1 0
0 1
103 0
102 8
100 1
2
0 12 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__110 
6
2 0
1 0
0 1
103 9
102 3
100 1
2
0 37 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__111 
5
2 0
1 0
0 1
103 10
102 0
3
0 83 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__112 
6
2 0
1 0
0 1
103 10
102 0
100 1
2
0 83 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__113 
6
2 0
1 0
0 1
103 10
102 0
100 1
2
0 83 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__114 
5
2 0
1 0
0 1
103 10
102 5
3
0 84 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__115 
6
2 0
1 0
0 1
103 10
102 5
100 1
2
0 84 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__116 
6
2 0
1 0
0 1
103 10
102 5
100 1
2
0 84 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__117 
5
2 0
1 0
0 1
103 10
102 6
3
0 85 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__118 
6
2 0
1 0
0 1
103 10
102 6
100 1
2
0 85 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__119 
6
2 0
1 0
0 1
103 10
102 6
100 1
2
0 85 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__12 
5
2 0
1 0
0 1
103 0
102 9
3
0 13 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__120 
5
2 0
1 0
0 1
103 10
102 7
3
0 86 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__121 
6
2 0
1 0
0 1
103 10
102 7
100 1
2
0 86 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__122 
6
2 0
1 0
0 1
103 10
102 7
100 1
2
0 86 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__123 
5
2 0
1 0
0 1
103 10
102 9
3
0 87 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__124 
6
2 0
1 0
0 1
103 10
102 9
100 1
2
0 87 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__125 
6
2 0
1 0
0 1
103 10
102 9
100 1
2
0 87 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__126 
5
2 0
1 0
0 1
103 10
102 10
3
0 88 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__127 
6
2 0
1 0
0 1
103 10
102 10
100 1
2
0 88 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__128 
6
2 0
1 0
0 1
103 10
102 10
100 1
2
0 88 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__129 
5
2 0
1 0
0 1
103 10
102 11
3
0 89 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__13 
6
2 0
1 0
0 1
103 0
102 9
100 1
2
0 13 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__130 
6
2 0
1 0
0 1
103 10
102 11
100 1
2
0 89 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__131 
6
2 0
1 0
0 1
103 10
102 11
100 1
2
0 89 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__132 
5
2 0
1 0
0 1
103 10
102 1
3
0 81 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__133 
6
2 0
1 0
0 1
103 10
102 1
100 1
2
0 81 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__134 
6
2 0
1 0
0 1
103 10
102 1
100 1
2
0 81 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__135 
5
2 0
1 0
0 1
103 10
102 2
3
0 82 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__136 
6
2 0
1 0
0 1
103 10
102 2
100 1
2
0 82 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__137 
6
2 0
1 0
0 1
103 10
102 2
100 1
2
0 82 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__138 
5
2 0
1 0
0 1
103 10
102 3
3
0 39 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__139 
6
2 0
1 0
0 1
103 10
102 3
100 1
2
0 39 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__14 
6
2 0
1 0
0 1
103 0
102 9
100 1
2
0 13 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__140 
6
2 0
1 0
0 1
103 10
102 3
100 1
2
0 39 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__141 
5
2 0
1 0
0 1
103 11
102 7
3
0 91 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__142 
6
2 0
1 0
0 1
103 11
102 7
100 1
2
0 91 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__143 
6
2 0
1 0
0 1
103 11
102 7
100 1
2
0 91 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__144 
5
2 0
1 0
0 1
103 11
102 11
3
0 92 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__145 
6
2 0
1 0
0 1
103 11
102 11
100 1
2
0 92 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__146 
6
2 0
1 0
0 1
103 11
102 11
100 1
2
0 92 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__147 
5
2 0
1 0
0 1
103 11
102 1
3
0 90 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__148 
6
2 0
1 0
0 1
103 11
102 1
100 1
2
0 90 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__149 
6
2 0
1 0
0 1
103 11
102 1
100 1
2
0 90 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__15 
5
2 0
1 0
0 1
103 0
102 10
3
0 14 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__150 
5
2 0
1 0
0 1
103 11
102 3
3
0 41 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__151 
6
2 0
1 0
0 1
103 11
102 3
100 1
2
0 41 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__152 
6
2 0
1 0
0 1
103 11
102 3
100 1
2
0 41 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__153 
5
2 0
1 0
0 1
103 12
102 0
3
0 94 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__154 
6
2 0
1 0
0 1
103 12
102 0
100 1
2
0 94 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__155 
6
2 0
1 0
0 1
103 12
102 0
100 1
2
0 94 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__156 
5
2 0
1 0
0 1
103 12
102 5
3
0 95 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__157 
6
2 0
1 0
0 1
103 12
102 5
100 1
2
0 95 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__158 
6
2 0
1 0
0 1
103 12
102 5
100 1
2
0 95 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__159 
5
2 0
1 0
0 1
103 12
102 7
3
0 96 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__16 
6
2 0
1 0
0 1
103 0
102 10
100 1
2
0 14 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__160 
6
2 0
1 0
0 1
103 12
102 7
100 1
2
0 96 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__161 
6
2 0
1 0
0 1
103 12
102 7
100 1
2
0 96 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__162 
5
2 0
1 0
0 1
103 12
102 8
3
0 97 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__163 
6
2 0
1 0
0 1
103 12
102 8
100 1
2
0 97 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__164 
6
2 0
1 0
0 1
103 12
102 8
100 1
2
0 97 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__165 
5
2 0
1 0
0 1
103 12
102 9
3
0 98 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__166 
6
2 0
1 0
0 1
103 12
102 9
100 1
2
0 98 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__167 
6
2 0
1 0
0 1
103 12
102 9
100 1
2
0 98 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__168 
5
2 0
1 0
0 1
103 12
102 11
3
0 99 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__169 
6
2 0
1 0
0 1
103 12
102 11
100 1
2
0 99 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__17 
6
2 0
1 0
0 1
103 0
102 10
100 1
2
0 14 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__170 
6
2 0
1 0
0 1
103 12
102 11
100 1
2
0 99 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__171 
5
2 0
1 0
0 1
103 12
102 1
3
0 93 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__172 
6
2 0
1 0
0 1
103 12
102 1
100 1
2
0 93 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__173 
6
2 0
1 0
0 1
103 12
102 1
100 1
2
0 93 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__174 
5
2 0
1 0
0 1
103 12
102 3
3
0 43 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__175 
6
2 0
1 0
0 1
103 12
102 3
100 1
2
0 43 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__176 
6
2 0
1 0
0 1
103 12
102 3
100 1
2
0 43 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__177 
5
2 0
1 0
0 1
103 1
102 5
3
0 45 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__178 
6
2 0
1 0
0 1
103 1
102 5
100 1
2
0 45 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__179 
6
2 0
1 0
0 1
103 1
102 5
100 1
2
0 45 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__18 
5
2 0
1 0
0 1
103 0
102 11
3
0 15 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__180 
5
2 0
1 0
0 1
103 1
102 7
3
0 46 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__181 
6
2 0
1 0
0 1
103 1
102 7
100 1
2
0 46 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__182 
6
2 0
1 0
0 1
103 1
102 7
100 1
2
0 46 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__183 
5
2 0
1 0
0 1
103 1
102 11
3
0 47 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__184 
6
2 0
1 0
0 1
103 1
102 11
100 1
2
0 47 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__185 
6
2 0
1 0
0 1
103 1
102 11
100 1
2
0 47 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__186 
5
2 0
1 0
0 1
103 1
102 1
3
0 44 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__187 
6
2 0
1 0
0 1
103 1
102 1
100 1
2
0 44 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__188 
6
2 0
1 0
0 1
103 1
102 1
100 1
2
0 44 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__189 
5
2 0
1 0
0 1
103 1
102 3
3
0 16 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__19 
6
2 0
1 0
0 1
103 0
102 11
100 1
2
0 15 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__190 
6
2 0
1 0
0 1
103 1
102 3
100 1
2
0 16 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__191 
6
2 0
1 0
0 1
103 1
102 3
100 1
2
0 16 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__192 
5
2 0
1 0
0 1
103 2
102 0
3
0 49 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__193 
6
2 0
1 0
0 1
103 2
102 0
100 1
2
0 49 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__194 
6
2 0
1 0
0 1
103 2
102 0
100 1
2
0 49 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__195 
5
2 0
1 0
0 1
103 2
102 5
3
0 50 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__196 
6
2 0
1 0
0 1
103 2
102 5
100 1
2
0 50 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__197 
6
2 0
1 0
0 1
103 2
102 5
100 1
2
0 50 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__198 
5
2 0
1 0
0 1
103 2
102 7
3
0 51 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__199 
6
2 0
1 0
0 1
103 2
102 7
100 1
2
0 51 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__2 
6
2 0
1 0
0 1
103 0
102 5
100 1
2
0 9 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__20 
6
2 0
1 0
0 1
103 0
102 11
100 1
2
0 15 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__200 
6
2 0
1 0
0 1
103 2
102 7
100 1
2
0 51 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__201 
5
2 0
1 0
0 1
103 2
102 9
3
0 52 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__202 
6
2 0
1 0
0 1
103 2
102 9
100 1
2
0 52 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__203 
6
2 0
1 0
0 1
103 2
102 9
100 1
2
0 52 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__204 
5
2 0
1 0
0 1
103 2
102 10
3
0 53 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__205 
6
2 0
1 0
0 1
103 2
102 10
100 1
2
0 53 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__206 
6
2 0
1 0
0 1
103 2
102 10
100 1
2
0 53 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__207 
5
2 0
1 0
0 1
103 2
102 11
3
0 54 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__208 
6
2 0
1 0
0 1
103 2
102 11
100 1
2
0 54 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__209 
6
2 0
1 0
0 1
103 2
102 11
100 1
2
0 54 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__21 
5
2 0
1 0
0 1
103 0
102 1
3
0 7 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__210 
5
2 0
1 0
0 1
103 2
102 1
3
0 48 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__211 
6
2 0
1 0
0 1
103 2
102 1
100 1
2
0 48 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__212 
6
2 0
1 0
0 1
103 2
102 1
100 1
2
0 48 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__213 
5
2 0
1 0
0 1
103 2
102 3
3
0 18 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__214 
6
2 0
1 0
0 1
103 2
102 3
100 1
2
0 18 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__215 
6
2 0
1 0
0 1
103 2
102 3
100 1
2
0 18 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__216 
5
2 0
1 0
0 1
103 3
102 7
3
0 56 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__217 
6
2 0
1 0
0 1
103 3
102 7
100 1
2
0 56 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__218 
6
2 0
1 0
0 1
103 3
102 7
100 1
2
0 56 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__219 
5
2 0
1 0
0 1
103 3
102 9
3
0 57 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__22 
6
2 0
1 0
0 1
103 0
102 1
100 1
2
0 7 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__220 
6
2 0
1 0
0 1
103 3
102 9
100 1
2
0 57 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__221 
6
2 0
1 0
0 1
103 3
102 9
100 1
2
0 57 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__222 
5
2 0
1 0
0 1
103 3
102 1
3
0 55 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__223 
6
2 0
1 0
0 1
103 3
102 1
100 1
2
0 55 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__224 
6
2 0
1 0
0 1
103 3
102 1
100 1
2
0 55 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__225 
5
2 0
1 0
0 1
103 3
102 3
3
0 20 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__226 
6
2 0
1 0
0 1
103 3
102 3
100 1
2
0 20 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__227 
6
2 0
1 0
0 1
103 3
102 3
100 1
2
0 20 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__228 
5
2 0
1 0
0 1
103 4
102 0
3
0 23 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__229 
6
2 0
1 0
0 1
103 4
102 0
100 1
2
0 23 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__23 
6
2 0
1 0
0 1
103 0
102 1
100 1
2
0 7 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__230 
6
2 0
1 0
0 1
103 4
102 0
100 1
2
0 23 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__231 
5
2 0
1 0
0 1
103 4
102 5
3
0 24 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__232 
6
2 0
1 0
0 1
103 4
102 5
100 1
2
0 24 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__233 
6
2 0
1 0
0 1
103 4
102 5
100 1
2
0 24 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__234 
5
2 0
1 0
0 1
103 4
102 7
3
0 25 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__235 
6
2 0
1 0
0 1
103 4
102 7
100 1
2
0 25 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__236 
6
2 0
1 0
0 1
103 4
102 7
100 1
2
0 25 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__237 
5
2 0
1 0
0 1
103 4
102 8
3
0 26 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__238 
6
2 0
1 0
0 1
103 4
102 8
100 1
2
0 26 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__239 
6
2 0
1 0
0 1
103 4
102 8
100 1
2
0 26 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__24 
5
2 0
1 0
0 1
103 0
102 2
3
0 8 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__240 
5
2 0
1 0
0 1
103 4
102 9
3
0 27 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__241 
6
2 0
1 0
0 1
103 4
102 9
100 1
2
0 27 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__242 
6
2 0
1 0
0 1
103 4
102 9
100 1
2
0 27 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__243 
5
2 0
1 0
0 1
103 4
102 10
3
0 28 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__244 
6
2 0
1 0
0 1
103 4
102 10
100 1
2
0 28 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__245 
6
2 0
1 0
0 1
103 4
102 10
100 1
2
0 28 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__246 
5
2 0
1 0
0 1
103 4
102 11
3
0 29 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__247 
6
2 0
1 0
0 1
103 4
102 11
100 1
2
0 29 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__248 
6
2 0
1 0
0 1
103 4
102 11
100 1
2
0 29 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__249 
5
2 0
1 0
0 1
103 4
102 12
3
0 21 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__25 
6
2 0
1 0
0 1
103 0
102 2
100 1
2
0 8 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__250 
6
2 0
1 0
0 1
103 4
102 12
100 1
2
0 21 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__251 
6
2 0
1 0
0 1
103 4
102 12
100 1
2
0 21 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__252 
5
2 0
1 0
0 1
103 4
102 1
3
0 22 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__253 
6
2 0
1 0
0 1
103 4
102 1
100 1
2
0 22 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__254 
6
2 0
1 0
0 1
103 4
102 1
100 1
2
0 22 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__255 
5
2 0
1 0
0 1
103 4
102 3
3
0 6 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__256 
6
2 0
1 0
0 1
103 4
102 3
100 1
2
0 6 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__257 
6
2 0
1 0
0 1
103 4
102 3
100 1
2
0 6 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__258 
5
2 2
1 0
0 1
103 0
102 5
3
0 3 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__259 
6
2 2
1 0
0 1
103 0
102 5
100 1
2
0 3 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__26 
6
2 0
1 0
0 1
103 0
102 2
100 1
2
0 8 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__260 
6
2 2
1 0
0 1
103 0
102 5
100 1
2
0 3 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__261 
5
2 2
1 0
0 1
103 0
102 7
3
0 9 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__262 
6
2 2
1 0
0 1
103 0
102 7
100 1
2
0 9 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__263 
6
2 2
1 0
0 1
103 0
102 7
100 1
2
0 9 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__264 
5
2 2
1 0
0 1
103 0
102 8
3
0 10 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__265 
6
2 2
1 0
0 1
103 0
102 8
100 1
2
0 10 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__266 
6
2 2
1 0
0 1
103 0
102 8
100 1
2
0 10 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__267 
5
2 2
1 0
0 1
103 0
102 9
3
0 11 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__268 
6
2 2
1 0
0 1
103 0
102 9
100 1
2
0 11 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__269 
6
2 2
1 0
0 1
103 0
102 9
100 1
2
0 11 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__27 
5
2 0
1 0
0 1
103 0
102 3
3
0 4 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__270 
5
2 2
1 0
0 1
103 0
102 10
3
0 12 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__271 
6
2 2
1 0
0 1
103 0
102 10
100 1
2
0 12 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__272 
6
2 2
1 0
0 1
103 0
102 10
100 1
2
0 12 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__273 
5
2 2
1 0
0 1
103 0
102 11
3
0 13 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__274 
6
2 2
1 0
0 1
103 0
102 11
100 1
2
0 13 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__275 
6
2 2
1 0
0 1
103 0
102 11
100 1
2
0 13 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__276 
5
2 2
1 0
0 1
103 0
102 12
3
0 14 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__277 
6
2 2
1 0
0 1
103 0
102 12
100 1
2
0 14 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__278 
6
2 2
1 0
0 1
103 0
102 12
100 1
2
0 14 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__279 
5
2 2
1 0
0 1
103 0
102 1
3
0 15 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__28 
6
2 0
1 0
0 1
103 0
102 3
100 1
2
0 4 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__280 
6
2 2
1 0
0 1
103 0
102 1
100 1
2
0 15 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__281 
6
2 2
1 0
0 1
103 0
102 1
100 1
2
0 15 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__282 
5
2 2
1 0
0 1
103 0
102 3
3
0 7 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__283 
6
2 2
1 0
0 1
103 0
102 3
100 1
2
0 7 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__284 
6
2 2
1 0
0 1
103 0
102 3
100 1
2
0 7 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__285 
5
2 2
1 0
0 1
103 0
102 4
3
0 8 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__286 
6
2 2
1 0
0 1
103 0
102 4
100 1
2
0 8 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__287 
6
2 2
1 0
0 1
103 0
102 4
100 1
2
0 8 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__288 
5
2 2
1 0
0 1
103 5
102 5
3
0 30 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__289 
6
2 2
1 0
0 1
103 5
102 5
100 1
2
0 30 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__29 
6
2 0
1 0
0 1
103 0
102 3
100 1
2
0 4 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__290 
6
2 2
1 0
0 1
103 5
102 5
100 1
2
0 30 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__291 
5
2 2
1 0
0 1
103 5
102 7
3
0 58 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__292 
6
2 2
1 0
0 1
103 5
102 7
100 1
2
0 58 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__293 
6
2 2
1 0
0 1
103 5
102 7
100 1
2
0 58 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__294 
5
2 2
1 0
0 1
103 5
102 1
3
0 59 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__295 
6
2 2
1 0
0 1
103 5
102 1
100 1
2
0 59 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__296 
6
2 2
1 0
0 1
103 5
102 1
100 1
2
0 59 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__297 
5
2 2
1 0
0 1
103 6
102 5
3
0 32 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__298 
6
2 2
1 0
0 1
103 6
102 5
100 1
2
0 32 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__299 
6
2 2
1 0
0 1
103 6
102 5
100 1
2
0 32 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__3 
5
2 0
1 0
0 1
103 0
102 6
3
0 10 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__30 
5
2 0
1 0
0 1
103 5
102 5
3
0 58 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__300 
5
2 2
1 0
0 1
103 6
102 7
3
0 62 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__301 
6
2 2
1 0
0 1
103 6
102 7
100 1
2
0 62 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__302 
6
2 2
1 0
0 1
103 6
102 7
100 1
2
0 62 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__303 
5
2 2
1 0
0 1
103 6
102 8
3
0 63 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__304 
6
2 2
1 0
0 1
103 6
102 8
100 1
2
0 63 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__305 
6
2 2
1 0
0 1
103 6
102 8
100 1
2
0 63 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__306 
5
2 2
1 0
0 1
103 6
102 9
3
0 64 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__307 
6
2 2
1 0
0 1
103 6
102 9
100 1
2
0 64 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__308 
6
2 2
1 0
0 1
103 6
102 9
100 1
2
0 64 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__309 
5
2 2
1 0
0 1
103 6
102 11
3
0 65 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__31 
6
2 0
1 0
0 1
103 5
102 5
100 1
2
0 58 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__310 
6
2 2
1 0
0 1
103 6
102 11
100 1
2
0 65 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__311 
6
2 2
1 0
0 1
103 6
102 11
100 1
2
0 65 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__312 
5
2 2
1 0
0 1
103 6
102 1
3
0 66 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__313 
6
2 2
1 0
0 1
103 6
102 1
100 1
2
0 66 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__314 
6
2 2
1 0
0 1
103 6
102 1
100 1
2
0 66 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__315 
5
2 2
1 0
0 1
103 6
102 3
3
0 60 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__316 
6
2 2
1 0
0 1
103 6
102 3
100 1
2
0 60 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__317 
6
2 2
1 0
0 1
103 6
102 3
100 1
2
0 60 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__318 
5
2 2
1 0
0 1
103 6
102 4
3
0 61 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__319 
6
2 2
1 0
0 1
103 6
102 4
100 1
2
0 61 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__32 
6
2 0
1 0
0 1
103 5
102 5
100 1
2
0 58 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__320 
6
2 2
1 0
0 1
103 6
102 4
100 1
2
0 61 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__321 
5
2 2
1 0
0 1
103 7
102 5
3
0 34 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__322 
6
2 2
1 0
0 1
103 7
102 5
100 1
2
0 34 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__323 
6
2 2
1 0
0 1
103 7
102 5
100 1
2
0 34 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__324 
5
2 2
1 0
0 1
103 7
102 9
3
0 68 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__325 
6
2 2
1 0
0 1
103 7
102 9
100 1
2
0 68 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__326 
6
2 2
1 0
0 1
103 7
102 9
100 1
2
0 68 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__327 
5
2 2
1 0
0 1
103 7
102 11
3
0 69 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__328 
6
2 2
1 0
0 1
103 7
102 11
100 1
2
0 69 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__329 
6
2 2
1 0
0 1
103 7
102 11
100 1
2
0 69 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__33 
5
2 0
1 0
0 1
103 5
102 11
3
0 59 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__330 
5
2 2
1 0
0 1
103 7
102 1
3
0 70 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__331 
6
2 2
1 0
0 1
103 7
102 1
100 1
2
0 70 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__332 
6
2 2
1 0
0 1
103 7
102 1
100 1
2
0 70 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__333 
5
2 2
1 0
0 1
103 7
102 3
3
0 67 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__334 
6
2 2
1 0
0 1
103 7
102 3
100 1
2
0 67 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__335 
6
2 2
1 0
0 1
103 7
102 3
100 1
2
0 67 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__336 
5
2 2
1 0
0 1
103 8
102 5
3
0 35 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__337 
6
2 2
1 0
0 1
103 8
102 5
100 1
2
0 35 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__338 
6
2 2
1 0
0 1
103 8
102 5
100 1
2
0 35 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__339 
5
2 2
1 0
0 1
103 8
102 6
3
0 73 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__34 
6
2 0
1 0
0 1
103 5
102 11
100 1
2
0 59 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__340 
6
2 2
1 0
0 1
103 8
102 6
100 1
2
0 73 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__341 
6
2 2
1 0
0 1
103 8
102 6
100 1
2
0 73 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__342 
5
2 2
1 0
0 1
103 8
102 7
3
0 74 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__343 
6
2 2
1 0
0 1
103 8
102 7
100 1
2
0 74 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__344 
6
2 2
1 0
0 1
103 8
102 7
100 1
2
0 74 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__345 
5
2 2
1 0
0 1
103 8
102 8
3
0 75 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__346 
6
2 2
1 0
0 1
103 8
102 8
100 1
2
0 75 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__347 
6
2 2
1 0
0 1
103 8
102 8
100 1
2
0 75 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__348 
5
2 2
1 0
0 1
103 8
102 9
3
0 76 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__349 
6
2 2
1 0
0 1
103 8
102 9
100 1
2
0 76 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__35 
6
2 0
1 0
0 1
103 5
102 11
100 1
2
0 59 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__350 
6
2 2
1 0
0 1
103 8
102 9
100 1
2
0 76 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__351 
5
2 2
1 0
0 1
103 8
102 11
3
0 77 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__352 
6
2 2
1 0
0 1
103 8
102 11
100 1
2
0 77 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__353 
6
2 2
1 0
0 1
103 8
102 11
100 1
2
0 77 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__354 
5
2 2
1 0
0 1
103 8
102 12
3
0 78 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__355 
6
2 2
1 0
0 1
103 8
102 12
100 1
2
0 78 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__356 
6
2 2
1 0
0 1
103 8
102 12
100 1
2
0 78 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__357 
5
2 2
1 0
0 1
103 8
102 1
3
0 79 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__358 
6
2 2
1 0
0 1
103 8
102 1
100 1
2
0 79 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__359 
6
2 2
1 0
0 1
103 8
102 1
100 1
2
0 79 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__36 
5
2 0
1 0
0 1
103 5
102 3
3
0 31 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__360 
5
2 2
1 0
0 1
103 8
102 3
3
0 71 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__361 
6
2 2
1 0
0 1
103 8
102 3
100 1
2
0 71 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__362 
6
2 2
1 0
0 1
103 8
102 3
100 1
2
0 71 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__363 
5
2 2
1 0
0 1
103 8
102 4
3
0 72 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__364 
6
2 2
1 0
0 1
103 8
102 4
100 1
2
0 72 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__365 
6
2 2
1 0
0 1
103 8
102 4
100 1
2
0 72 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__366 
5
2 2
1 0
0 1
103 9
102 11
3
0 80 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__367 
6
2 2
1 0
0 1
103 9
102 11
100 1
2
0 80 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__368 
6
2 2
1 0
0 1
103 9
102 11
100 1
2
0 80 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__369 
5
2 2
1 0
0 1
103 10
102 5
3
0 38 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__37 
6
2 0
1 0
0 1
103 5
102 3
100 1
2
0 31 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__370 
6
2 2
1 0
0 1
103 10
102 5
100 1
2
0 38 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__371 
6
2 2
1 0
0 1
103 10
102 5
100 1
2
0 38 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__372 
5
2 2
1 0
0 1
103 10
102 6
3
0 83 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__373 
6
2 2
1 0
0 1
103 10
102 6
100 1
2
0 83 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__374 
6
2 2
1 0
0 1
103 10
102 6
100 1
2
0 83 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__375 
5
2 2
1 0
0 1
103 10
102 7
3
0 84 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__376 
6
2 2
1 0
0 1
103 10
102 7
100 1
2
0 84 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__377 
6
2 2
1 0
0 1
103 10
102 7
100 1
2
0 84 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__378 
5
2 2
1 0
0 1
103 10
102 8
3
0 85 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__379 
6
2 2
1 0
0 1
103 10
102 8
100 1
2
0 85 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__38 
6
2 0
1 0
0 1
103 5
102 3
100 1
2
0 31 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__380 
6
2 2
1 0
0 1
103 10
102 8
100 1
2
0 85 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__381 
5
2 2
1 0
0 1
103 10
102 9
3
0 86 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__382 
6
2 2
1 0
0 1
103 10
102 9
100 1
2
0 86 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__383 
6
2 2
1 0
0 1
103 10
102 9
100 1
2
0 86 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__384 
5
2 2
1 0
0 1
103 10
102 11
3
0 87 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__385 
6
2 2
1 0
0 1
103 10
102 11
100 1
2
0 87 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__386 
6
2 2
1 0
0 1
103 10
102 11
100 1
2
0 87 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__387 
5
2 2
1 0
0 1
103 10
102 12
3
0 88 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__388 
6
2 2
1 0
0 1
103 10
102 12
100 1
2
0 88 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__389 
6
2 2
1 0
0 1
103 10
102 12
100 1
2
0 88 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__39 
5
2 0
1 0
0 1
103 6
102 5
3
0 62 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__390 
5
2 2
1 0
0 1
103 10
102 1
3
0 89 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__391 
6
2 2
1 0
0 1
103 10
102 1
100 1
2
0 89 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__392 
6
2 2
1 0
0 1
103 10
102 1
100 1
2
0 89 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__393 
5
2 2
1 0
0 1
103 10
102 3
3
0 81 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__394 
6
2 2
1 0
0 1
103 10
102 3
100 1
2
0 81 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__395 
6
2 2
1 0
0 1
103 10
102 3
100 1
2
0 81 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__396 
5
2 2
1 0
0 1
103 10
102 4
3
0 82 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__397 
6
2 2
1 0
0 1
103 10
102 4
100 1
2
0 82 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__398 
6
2 2
1 0
0 1
103 10
102 4
100 1
2
0 82 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__399 
5
2 2
1 0
0 1
103 11
102 5
3
0 40 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__4 
6
2 0
1 0
0 1
103 0
102 6
100 1
2
0 10 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__40 
6
2 0
1 0
0 1
103 6
102 5
100 1
2
0 62 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__400 
6
2 2
1 0
0 1
103 11
102 5
100 1
2
0 40 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__401 
6
2 2
1 0
0 1
103 11
102 5
100 1
2
0 40 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__402 
5
2 2
1 0
0 1
103 11
102 9
3
0 91 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__403 
6
2 2
1 0
0 1
103 11
102 9
100 1
2
0 91 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__404 
6
2 2
1 0
0 1
103 11
102 9
100 1
2
0 91 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__405 
5
2 2
1 0
0 1
103 11
102 1
3
0 92 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__406 
6
2 2
1 0
0 1
103 11
102 1
100 1
2
0 92 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__407 
6
2 2
1 0
0 1
103 11
102 1
100 1
2
0 92 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__408 
5
2 2
1 0
0 1
103 11
102 3
3
0 90 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__409 
6
2 2
1 0
0 1
103 11
102 3
100 1
2
0 90 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__41 
6
2 0
1 0
0 1
103 6
102 5
100 1
2
0 62 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__410 
6
2 2
1 0
0 1
103 11
102 3
100 1
2
0 90 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__411 
5
2 2
1 0
0 1
103 12
102 5
3
0 42 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__412 
6
2 2
1 0
0 1
103 12
102 5
100 1
2
0 42 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__413 
6
2 2
1 0
0 1
103 12
102 5
100 1
2
0 42 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__414 
5
2 2
1 0
0 1
103 12
102 6
3
0 94 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__415 
6
2 2
1 0
0 1
103 12
102 6
100 1
2
0 94 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__416 
6
2 2
1 0
0 1
103 12
102 6
100 1
2
0 94 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__417 
5
2 2
1 0
0 1
103 12
102 7
3
0 95 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__418 
6
2 2
1 0
0 1
103 12
102 7
100 1
2
0 95 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__419 
6
2 2
1 0
0 1
103 12
102 7
100 1
2
0 95 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__42 
5
2 0
1 0
0 1
103 6
102 6
3
0 63 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__420 
5
2 2
1 0
0 1
103 12
102 9
3
0 96 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__421 
6
2 2
1 0
0 1
103 12
102 9
100 1
2
0 96 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__422 
6
2 2
1 0
0 1
103 12
102 9
100 1
2
0 96 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__423 
5
2 2
1 0
0 1
103 12
102 10
3
0 97 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__424 
6
2 2
1 0
0 1
103 12
102 10
100 1
2
0 97 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__425 
6
2 2
1 0
0 1
103 12
102 10
100 1
2
0 97 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__426 
5
2 2
1 0
0 1
103 12
102 11
3
0 98 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__427 
6
2 2
1 0
0 1
103 12
102 11
100 1
2
0 98 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__428 
6
2 2
1 0
0 1
103 12
102 11
100 1
2
0 98 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__429 
5
2 2
1 0
0 1
103 12
102 1
3
0 99 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__43 
6
2 0
1 0
0 1
103 6
102 6
100 1
2
0 63 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__430 
6
2 2
1 0
0 1
103 12
102 1
100 1
2
0 99 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__431 
6
2 2
1 0
0 1
103 12
102 1
100 1
2
0 99 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__432 
5
2 2
1 0
0 1
103 12
102 3
3
0 93 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__433 
6
2 2
1 0
0 1
103 12
102 3
100 1
2
0 93 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__434 
6
2 2
1 0
0 1
103 12
102 3
100 1
2
0 93 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__435 
5
2 2
1 0
0 1
103 1
102 7
3
0 45 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__436 
6
2 2
1 0
0 1
103 1
102 7
100 1
2
0 45 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__437 
6
2 2
1 0
0 1
103 1
102 7
100 1
2
0 45 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__438 
5
2 2
1 0
0 1
103 1
102 9
3
0 46 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__439 
6
2 2
1 0
0 1
103 1
102 9
100 1
2
0 46 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__44 
6
2 0
1 0
0 1
103 6
102 6
100 1
2
0 63 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__440 
6
2 2
1 0
0 1
103 1
102 9
100 1
2
0 46 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__441 
5
2 2
1 0
0 1
103 1
102 1
3
0 47 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__442 
6
2 2
1 0
0 1
103 1
102 1
100 1
2
0 47 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__443 
6
2 2
1 0
0 1
103 1
102 1
100 1
2
0 47 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__444 
5
2 2
1 0
0 1
103 1
102 3
3
0 44 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__445 
6
2 2
1 0
0 1
103 1
102 3
100 1
2
0 44 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__446 
6
2 2
1 0
0 1
103 1
102 3
100 1
2
0 44 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__447 
5
2 2
1 0
0 1
103 2
102 5
3
0 17 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__448 
6
2 2
1 0
0 1
103 2
102 5
100 1
2
0 17 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__449 
6
2 2
1 0
0 1
103 2
102 5
100 1
2
0 17 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__45 
5
2 0
1 0
0 1
103 6
102 7
3
0 64 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__450 
5
2 2
1 0
0 1
103 2
102 6
3
0 49 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__451 
6
2 2
1 0
0 1
103 2
102 6
100 1
2
0 49 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__452 
6
2 2
1 0
0 1
103 2
102 6
100 1
2
0 49 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__453 
5
2 2
1 0
0 1
103 2
102 7
3
0 50 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__454 
6
2 2
1 0
0 1
103 2
102 7
100 1
2
0 50 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__455 
6
2 2
1 0
0 1
103 2
102 7
100 1
2
0 50 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__456 
5
2 2
1 0
0 1
103 2
102 9
3
0 51 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__457 
6
2 2
1 0
0 1
103 2
102 9
100 1
2
0 51 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__458 
6
2 2
1 0
0 1
103 2
102 9
100 1
2
0 51 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__459 
5
2 2
1 0
0 1
103 2
102 11
3
0 52 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__46 
6
2 0
1 0
0 1
103 6
102 7
100 1
2
0 64 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__460 
6
2 2
1 0
0 1
103 2
102 11
100 1
2
0 52 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__461 
6
2 2
1 0
0 1
103 2
102 11
100 1
2
0 52 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__462 
5
2 2
1 0
0 1
103 2
102 12
3
0 53 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__463 
6
2 2
1 0
0 1
103 2
102 12
100 1
2
0 53 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__464 
6
2 2
1 0
0 1
103 2
102 12
100 1
2
0 53 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__465 
5
2 2
1 0
0 1
103 2
102 1
3
0 54 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__466 
6
2 2
1 0
0 1
103 2
102 1
100 1
2
0 54 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__467 
6
2 2
1 0
0 1
103 2
102 1
100 1
2
0 54 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__468 
5
2 2
1 0
0 1
103 2
102 3
3
0 48 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__469 
6
2 2
1 0
0 1
103 2
102 3
100 1
2
0 48 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__47 
6
2 0
1 0
0 1
103 6
102 7
100 1
2
0 64 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__470 
6
2 2
1 0
0 1
103 2
102 3
100 1
2
0 48 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__471 
5
2 2
1 0
0 1
103 3
102 5
3
0 19 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__472 
6
2 2
1 0
0 1
103 3
102 5
100 1
2
0 19 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__473 
6
2 2
1 0
0 1
103 3
102 5
100 1
2
0 19 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__474 
5
2 2
1 0
0 1
103 3
102 9
3
0 56 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__475 
6
2 2
1 0
0 1
103 3
102 9
100 1
2
0 56 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__476 
6
2 2
1 0
0 1
103 3
102 9
100 1
2
0 56 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__477 
5
2 2
1 0
0 1
103 3
102 11
3
0 57 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__478 
6
2 2
1 0
0 1
103 3
102 11
100 1
2
0 57 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__479 
6
2 2
1 0
0 1
103 3
102 11
100 1
2
0 57 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__48 
5
2 0
1 0
0 1
103 6
102 9
3
0 65 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__480 
5
2 2
1 0
0 1
103 3
102 3
3
0 55 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__481 
6
2 2
1 0
0 1
103 3
102 3
100 1
2
0 55 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__482 
6
2 2
1 0
0 1
103 3
102 3
100 1
2
0 55 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__483 
5
2 2
1 0
0 1
103 4
102 5
3
0 5 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__484 
6
2 2
1 0
0 1
103 4
102 5
100 1
2
0 5 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__485 
6
2 2
1 0
0 1
103 4
102 5
100 1
2
0 5 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__486 
5
2 2
1 0
0 1
103 4
102 6
3
0 23 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__487 
6
2 2
1 0
0 1
103 4
102 6
100 1
2
0 23 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__488 
6
2 2
1 0
0 1
103 4
102 6
100 1
2
0 23 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__489 
5
2 2
1 0
0 1
103 4
102 7
3
0 24 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__49 
6
2 0
1 0
0 1
103 6
102 9
100 1
2
0 65 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__490 
6
2 2
1 0
0 1
103 4
102 7
100 1
2
0 24 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__491 
6
2 2
1 0
0 1
103 4
102 7
100 1
2
0 24 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__492 
5
2 2
1 0
0 1
103 4
102 9
3
0 25 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__493 
6
2 2
1 0
0 1
103 4
102 9
100 1
2
0 25 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__494 
6
2 2
1 0
0 1
103 4
102 9
100 1
2
0 25 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__495 
5
2 2
1 0
0 1
103 4
102 10
3
0 26 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__496 
6
2 2
1 0
0 1
103 4
102 10
100 1
2
0 26 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__497 
6
2 2
1 0
0 1
103 4
102 10
100 1
2
0 26 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__498 
5
2 2
1 0
0 1
103 4
102 11
3
0 27 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__499 
6
2 2
1 0
0 1
103 4
102 11
100 1
2
0 27 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__5 
6
2 0
1 0
0 1
103 0
102 6
100 1
2
0 10 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__50 
6
2 0
1 0
0 1
103 6
102 9
100 1
2
0 65 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__500 
6
2 2
1 0
0 1
103 4
102 11
100 1
2
0 27 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__501 
5
2 2
1 0
0 1
103 4
102 12
3
0 28 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__502 
6
2 2
1 0
0 1
103 4
102 12
100 1
2
0 28 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__503 
6
2 2
1 0
0 1
103 4
102 12
100 1
2
0 28 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__504 
5
2 2
1 0
0 1
103 4
102 1
3
0 29 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__505 
6
2 2
1 0
0 1
103 4
102 1
100 1
2
0 29 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__506 
6
2 2
1 0
0 1
103 4
102 1
100 1
2
0 29 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__507 
5
2 2
1 0
0 1
103 4
102 2
3
0 21 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__508 
6
2 2
1 0
0 1
103 4
102 2
100 1
2
0 21 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__509 
6
2 2
1 0
0 1
103 4
102 2
100 1
2
0 21 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__51 
5
2 0
1 0
0 1
103 6
102 11
3
0 66 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__510 
5
2 2
1 0
0 1
103 4
102 3
3
0 22 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__511 
6
2 2
1 0
0 1
103 4
102 3
100 1
2
0 22 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__512 
6
2 2
1 0
0 1
103 4
102 3
100 1
2
0 22 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__513 
5
2 1
1 0
0 1
103 5
102 0
3
0 3 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__514 
6
2 1
1 0
0 1
103 5
102 0
100 1
2
0 3 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__515 
6
2 1
1 0
0 1
103 5
102 0
100 1
2
0 3 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__516 
5
2 1
1 0
0 1
103 5
102 6
3
0 9 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__517 
6
2 1
1 0
0 1
103 5
102 6
100 1
2
0 9 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__518 
6
2 1
1 0
0 1
103 5
102 6
100 1
2
0 9 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__519 
5
2 1
1 0
0 1
103 5
102 7
3
0 10 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__52 
6
2 0
1 0
0 1
103 6
102 11
100 1
2
0 66 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__520 
6
2 1
1 0
0 1
103 5
102 7
100 1
2
0 10 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__521 
6
2 1
1 0
0 1
103 5
102 7
100 1
2
0 10 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__522 
5
2 1
1 0
0 1
103 5
102 8
3
0 11 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__523 
6
2 1
1 0
0 1
103 5
102 8
100 1
2
0 11 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__524 
6
2 1
1 0
0 1
103 5
102 8
100 1
2
0 11 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__525 
5
2 1
1 0
0 1
103 5
102 9
3
0 12 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__526 
6
2 1
1 0
0 1
103 5
102 9
100 1
2
0 12 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__527 
6
2 1
1 0
0 1
103 5
102 9
100 1
2
0 12 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__528 
5
2 1
1 0
0 1
103 5
102 10
3
0 13 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__529 
6
2 1
1 0
0 1
103 5
102 10
100 1
2
0 13 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__53 
6
2 0
1 0
0 1
103 6
102 11
100 1
2
0 66 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__530 
6
2 1
1 0
0 1
103 5
102 10
100 1
2
0 13 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__531 
5
2 1
1 0
0 1
103 5
102 11
3
0 14 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__532 
6
2 1
1 0
0 1
103 5
102 11
100 1
2
0 14 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__533 
6
2 1
1 0
0 1
103 5
102 11
100 1
2
0 14 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__534 
5
2 1
1 0
0 1
103 5
102 12
3
0 15 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__535 
6
2 1
1 0
0 1
103 5
102 12
100 1
2
0 15 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__536 
6
2 1
1 0
0 1
103 5
102 12
100 1
2
0 15 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__537 
5
2 1
1 0
0 1
103 5
102 2
3
0 7 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__538 
6
2 1
1 0
0 1
103 5
102 2
100 1
2
0 7 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__539 
6
2 1
1 0
0 1
103 5
102 2
100 1
2
0 7 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__54 
5
2 0
1 0
0 1
103 6
102 1
3
0 60 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__540 
5
2 1
1 0
0 1
103 5
102 3
3
0 8 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__541 
6
2 1
1 0
0 1
103 5
102 3
100 1
2
0 8 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__542 
6
2 1
1 0
0 1
103 5
102 3
100 1
2
0 8 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__543 
5
2 1
1 0
0 1
103 5
102 4
3
0 4 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__544 
6
2 1
1 0
0 1
103 5
102 4
100 1
2
0 4 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__545 
6
2 1
1 0
0 1
103 5
102 4
100 1
2
0 4 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__546 
5
2 1
1 0
0 1
103 6
102 0
3
0 30 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__547 
6
2 1
1 0
0 1
103 6
102 0
100 1
2
0 30 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__548 
6
2 1
1 0
0 1
103 6
102 0
100 1
2
0 30 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__549 
5
2 1
1 0
0 1
103 6
102 6
3
0 58 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__55 
6
2 0
1 0
0 1
103 6
102 1
100 1
2
0 60 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__550 
6
2 1
1 0
0 1
103 6
102 6
100 1
2
0 58 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__551 
6
2 1
1 0
0 1
103 6
102 6
100 1
2
0 58 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__552 
5
2 1
1 0
0 1
103 6
102 12
3
0 59 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__553 
6
2 1
1 0
0 1
103 6
102 12
100 1
2
0 59 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__554 
6
2 1
1 0
0 1
103 6
102 12
100 1
2
0 59 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__555 
5
2 1
1 0
0 1
103 6
102 4
3
0 31 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__556 
6
2 1
1 0
0 1
103 6
102 4
100 1
2
0 31 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__557 
6
2 1
1 0
0 1
103 6
102 4
100 1
2
0 31 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__558 
5
2 1
1 0
0 1
103 7
102 0
3
0 32 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__559 
6
2 1
1 0
0 1
103 7
102 0
100 1
2
0 32 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__56 
6
2 0
1 0
0 1
103 6
102 1
100 1
2
0 60 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__560 
6
2 1
1 0
0 1
103 7
102 0
100 1
2
0 32 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__561 
5
2 1
1 0
0 1
103 7
102 6
3
0 62 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__562 
6
2 1
1 0
0 1
103 7
102 6
100 1
2
0 62 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__563 
6
2 1
1 0
0 1
103 7
102 6
100 1
2
0 62 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__564 
5
2 1
1 0
0 1
103 7
102 7
3
0 63 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__565 
6
2 1
1 0
0 1
103 7
102 7
100 1
2
0 63 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__566 
6
2 1
1 0
0 1
103 7
102 7
100 1
2
0 63 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__567 
5
2 1
1 0
0 1
103 7
102 8
3
0 64 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__568 
6
2 1
1 0
0 1
103 7
102 8
100 1
2
0 64 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__569 
6
2 1
1 0
0 1
103 7
102 8
100 1
2
0 64 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__57 
5
2 0
1 0
0 1
103 6
102 2
3
0 61 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__570 
5
2 1
1 0
0 1
103 7
102 10
3
0 65 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__571 
6
2 1
1 0
0 1
103 7
102 10
100 1
2
0 65 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__572 
6
2 1
1 0
0 1
103 7
102 10
100 1
2
0 65 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__573 
5
2 1
1 0
0 1
103 7
102 12
3
0 66 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__574 
6
2 1
1 0
0 1
103 7
102 12
100 1
2
0 66 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__575 
6
2 1
1 0
0 1
103 7
102 12
100 1
2
0 66 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__576 
5
2 1
1 0
0 1
103 7
102 2
3
0 60 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__577 
6
2 1
1 0
0 1
103 7
102 2
100 1
2
0 60 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__578 
6
2 1
1 0
0 1
103 7
102 2
100 1
2
0 60 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__579 
5
2 1
1 0
0 1
103 7
102 3
3
0 61 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__58 
6
2 0
1 0
0 1
103 6
102 2
100 1
2
0 61 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__580 
6
2 1
1 0
0 1
103 7
102 3
100 1
2
0 61 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__581 
6
2 1
1 0
0 1
103 7
102 3
100 1
2
0 61 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__582 
5
2 1
1 0
0 1
103 7
102 4
3
0 33 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__583 
6
2 1
1 0
0 1
103 7
102 4
100 1
2
0 33 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__584 
6
2 1
1 0
0 1
103 7
102 4
100 1
2
0 33 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__585 
5
2 1
1 0
0 1
103 8
102 0
3
0 34 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__586 
6
2 1
1 0
0 1
103 8
102 0
100 1
2
0 34 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__587 
6
2 1
1 0
0 1
103 8
102 0
100 1
2
0 34 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__588 
5
2 1
1 0
0 1
103 8
102 8
3
0 68 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__589 
6
2 1
1 0
0 1
103 8
102 8
100 1
2
0 68 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__59 
6
2 0
1 0
0 1
103 6
102 2
100 1
2
0 61 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__590 
6
2 1
1 0
0 1
103 8
102 8
100 1
2
0 68 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__591 
5
2 1
1 0
0 1
103 8
102 10
3
0 69 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__592 
6
2 1
1 0
0 1
103 8
102 10
100 1
2
0 69 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__593 
6
2 1
1 0
0 1
103 8
102 10
100 1
2
0 69 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__594 
5
2 1
1 0
0 1
103 8
102 12
3
0 70 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__595 
6
2 1
1 0
0 1
103 8
102 12
100 1
2
0 70 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__596 
6
2 1
1 0
0 1
103 8
102 12
100 1
2
0 70 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__597 
5
2 1
1 0
0 1
103 8
102 2
3
0 67 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__598 
6
2 1
1 0
0 1
103 8
102 2
100 1
2
0 67 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__599 
6
2 1
1 0
0 1
103 8
102 2
100 1
2
0 67 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__6 
5
2 0
1 0
0 1
103 0
102 7
3
0 11 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__60 
5
2 0
1 0
0 1
103 6
102 3
3
0 33 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__600 
5
2 1
1 0
0 1
103 9
102 0
3
0 35 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__601 
6
2 1
1 0
0 1
103 9
102 0
100 1
2
0 35 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__602 
6
2 1
1 0
0 1
103 9
102 0
100 1
2
0 35 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__603 
5
2 1
1 0
0 1
103 9
102 5
3
0 73 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__604 
6
2 1
1 0
0 1
103 9
102 5
100 1
2
0 73 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__605 
6
2 1
1 0
0 1
103 9
102 5
100 1
2
0 73 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__606 
5
2 1
1 0
0 1
103 9
102 6
3
0 74 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__607 
6
2 1
1 0
0 1
103 9
102 6
100 1
2
0 74 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__608 
6
2 1
1 0
0 1
103 9
102 6
100 1
2
0 74 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__609 
5
2 1
1 0
0 1
103 9
102 7
3
0 75 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__61 
6
2 0
1 0
0 1
103 6
102 3
100 1
2
0 33 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__610 
6
2 1
1 0
0 1
103 9
102 7
100 1
2
0 75 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__611 
6
2 1
1 0
0 1
103 9
102 7
100 1
2
0 75 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__612 
5
2 1
1 0
0 1
103 9
102 8
3
0 76 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__613 
6
2 1
1 0
0 1
103 9
102 8
100 1
2
0 76 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__614 
6
2 1
1 0
0 1
103 9
102 8
100 1
2
0 76 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__615 
5
2 1
1 0
0 1
103 9
102 10
3
0 77 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__616 
6
2 1
1 0
0 1
103 9
102 10
100 1
2
0 77 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__617 
6
2 1
1 0
0 1
103 9
102 10
100 1
2
0 77 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__618 
5
2 1
1 0
0 1
103 9
102 11
3
0 78 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__619 
6
2 1
1 0
0 1
103 9
102 11
100 1
2
0 78 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__62 
6
2 0
1 0
0 1
103 6
102 3
100 1
2
0 33 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__620 
6
2 1
1 0
0 1
103 9
102 11
100 1
2
0 78 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__621 
5
2 1
1 0
0 1
103 9
102 12
3
0 79 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__622 
6
2 1
1 0
0 1
103 9
102 12
100 1
2
0 79 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__623 
6
2 1
1 0
0 1
103 9
102 12
100 1
2
0 79 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__624 
5
2 1
1 0
0 1
103 9
102 2
3
0 71 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__625 
6
2 1
1 0
0 1
103 9
102 2
100 1
2
0 71 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__626 
6
2 1
1 0
0 1
103 9
102 2
100 1
2
0 71 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__627 
5
2 1
1 0
0 1
103 9
102 3
3
0 72 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__628 
6
2 1
1 0
0 1
103 9
102 3
100 1
2
0 72 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__629 
6
2 1
1 0
0 1
103 9
102 3
100 1
2
0 72 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__63 
5
2 0
1 0
0 1
103 7
102 7
3
0 68 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__630 
5
2 1
1 0
0 1
103 9
102 4
3
0 36 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__631 
6
2 1
1 0
0 1
103 9
102 4
100 1
2
0 36 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__632 
6
2 1
1 0
0 1
103 9
102 4
100 1
2
0 36 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__633 
5
2 1
1 0
0 1
103 10
102 10
3
0 80 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__634 
6
2 1
1 0
0 1
103 10
102 10
100 1
2
0 80 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__635 
6
2 1
1 0
0 1
103 10
102 10
100 1
2
0 80 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__636 
5
2 1
1 0
0 1
103 10
102 4
3
0 37 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__637 
6
2 1
1 0
0 1
103 10
102 4
100 1
2
0 37 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__638 
6
2 1
1 0
0 1
103 10
102 4
100 1
2
0 37 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__639 
5
2 1
1 0
0 1
103 11
102 0
3
0 38 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__64 
6
2 0
1 0
0 1
103 7
102 7
100 1
2
0 68 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__640 
6
2 1
1 0
0 1
103 11
102 0
100 1
2
0 38 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__641 
6
2 1
1 0
0 1
103 11
102 0
100 1
2
0 38 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__642 
5
2 1
1 0
0 1
103 11
102 5
3
0 83 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__643 
6
2 1
1 0
0 1
103 11
102 5
100 1
2
0 83 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__644 
6
2 1
1 0
0 1
103 11
102 5
100 1
2
0 83 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__645 
5
2 1
1 0
0 1
103 11
102 6
3
0 84 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__646 
6
2 1
1 0
0 1
103 11
102 6
100 1
2
0 84 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__647 
6
2 1
1 0
0 1
103 11
102 6
100 1
2
0 84 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__648 
5
2 1
1 0
0 1
103 11
102 7
3
0 85 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__649 
6
2 1
1 0
0 1
103 11
102 7
100 1
2
0 85 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__65 
6
2 0
1 0
0 1
103 7
102 7
100 1
2
0 68 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__650 
6
2 1
1 0
0 1
103 11
102 7
100 1
2
0 85 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__651 
5
2 1
1 0
0 1
103 11
102 8
3
0 86 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__652 
6
2 1
1 0
0 1
103 11
102 8
100 1
2
0 86 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__653 
6
2 1
1 0
0 1
103 11
102 8
100 1
2
0 86 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__654 
5
2 1
1 0
0 1
103 11
102 10
3
0 87 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__655 
6
2 1
1 0
0 1
103 11
102 10
100 1
2
0 87 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__656 
6
2 1
1 0
0 1
103 11
102 10
100 1
2
0 87 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__657 
5
2 1
1 0
0 1
103 11
102 11
3
0 88 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__658 
6
2 1
1 0
0 1
103 11
102 11
100 1
2
0 88 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__659 
6
2 1
1 0
0 1
103 11
102 11
100 1
2
0 88 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__66 
5
2 0
1 0
0 1
103 7
102 9
3
0 69 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__660 
5
2 1
1 0
0 1
103 11
102 12
3
0 89 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__661 
6
2 1
1 0
0 1
103 11
102 12
100 1
2
0 89 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__662 
6
2 1
1 0
0 1
103 11
102 12
100 1
2
0 89 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__663 
5
2 1
1 0
0 1
103 11
102 2
3
0 81 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__664 
6
2 1
1 0
0 1
103 11
102 2
100 1
2
0 81 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__665 
6
2 1
1 0
0 1
103 11
102 2
100 1
2
0 81 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__666 
5
2 1
1 0
0 1
103 11
102 3
3
0 82 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__667 
6
2 1
1 0
0 1
103 11
102 3
100 1
2
0 82 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__668 
6
2 1
1 0
0 1
103 11
102 3
100 1
2
0 82 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__669 
5
2 1
1 0
0 1
103 11
102 4
3
0 39 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__67 
6
2 0
1 0
0 1
103 7
102 9
100 1
2
0 69 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__670 
6
2 1
1 0
0 1
103 11
102 4
100 1
2
0 39 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__671 
6
2 1
1 0
0 1
103 11
102 4
100 1
2
0 39 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__672 
5
2 1
1 0
0 1
103 12
102 0
3
0 40 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__673 
6
2 1
1 0
0 1
103 12
102 0
100 1
2
0 40 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__674 
6
2 1
1 0
0 1
103 12
102 0
100 1
2
0 40 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__675 
5
2 1
1 0
0 1
103 12
102 8
3
0 91 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__676 
6
2 1
1 0
0 1
103 12
102 8
100 1
2
0 91 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__677 
6
2 1
1 0
0 1
103 12
102 8
100 1
2
0 91 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__678 
5
2 1
1 0
0 1
103 12
102 12
3
0 92 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__679 
6
2 1
1 0
0 1
103 12
102 12
100 1
2
0 92 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__68 
6
2 0
1 0
0 1
103 7
102 9
100 1
2
0 69 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__680 
6
2 1
1 0
0 1
103 12
102 12
100 1
2
0 92 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__681 
5
2 1
1 0
0 1
103 12
102 2
3
0 90 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__682 
6
2 1
1 0
0 1
103 12
102 2
100 1
2
0 90 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__683 
6
2 1
1 0
0 1
103 12
102 2
100 1
2
0 90 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__684 
5
2 1
1 0
0 1
103 12
102 4
3
0 41 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__685 
6
2 1
1 0
0 1
103 12
102 4
100 1
2
0 41 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__686 
6
2 1
1 0
0 1
103 12
102 4
100 1
2
0 41 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__687 
5
2 1
1 0
0 1
103 1
102 0
3
0 42 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__688 
6
2 1
1 0
0 1
103 1
102 0
100 1
2
0 42 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__689 
6
2 1
1 0
0 1
103 1
102 0
100 1
2
0 42 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__69 
5
2 0
1 0
0 1
103 7
102 11
3
0 70 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__690 
5
2 1
1 0
0 1
103 1
102 5
3
0 94 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__691 
6
2 1
1 0
0 1
103 1
102 5
100 1
2
0 94 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__692 
6
2 1
1 0
0 1
103 1
102 5
100 1
2
0 94 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__693 
5
2 1
1 0
0 1
103 1
102 6
3
0 95 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__694 
6
2 1
1 0
0 1
103 1
102 6
100 1
2
0 95 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__695 
6
2 1
1 0
0 1
103 1
102 6
100 1
2
0 95 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__696 
5
2 1
1 0
0 1
103 1
102 8
3
0 96 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__697 
6
2 1
1 0
0 1
103 1
102 8
100 1
2
0 96 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__698 
6
2 1
1 0
0 1
103 1
102 8
100 1
2
0 96 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__699 
5
2 1
1 0
0 1
103 1
102 9
3
0 97 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__7 
6
2 0
1 0
0 1
103 0
102 7
100 1
2
0 11 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__70 
6
2 0
1 0
0 1
103 7
102 11
100 1
2
0 70 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__700 
6
2 1
1 0
0 1
103 1
102 9
100 1
2
0 97 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__701 
6
2 1
1 0
0 1
103 1
102 9
100 1
2
0 97 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__702 
5
2 1
1 0
0 1
103 1
102 10
3
0 98 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__703 
6
2 1
1 0
0 1
103 1
102 10
100 1
2
0 98 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__704 
6
2 1
1 0
0 1
103 1
102 10
100 1
2
0 98 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__705 
5
2 1
1 0
0 1
103 1
102 12
3
0 99 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__706 
6
2 1
1 0
0 1
103 1
102 12
100 1
2
0 99 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__707 
6
2 1
1 0
0 1
103 1
102 12
100 1
2
0 99 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__708 
5
2 1
1 0
0 1
103 1
102 2
3
0 93 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__709 
6
2 1
1 0
0 1
103 1
102 2
100 1
2
0 93 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__71 
6
2 0
1 0
0 1
103 7
102 11
100 1
2
0 70 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__710 
6
2 1
1 0
0 1
103 1
102 2
100 1
2
0 93 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__711 
5
2 1
1 0
0 1
103 1
102 4
3
0 43 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__712 
6
2 1
1 0
0 1
103 1
102 4
100 1
2
0 43 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__713 
6
2 1
1 0
0 1
103 1
102 4
100 1
2
0 43 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__714 
5
2 1
1 0
0 1
103 2
102 6
3
0 45 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__715 
6
2 1
1 0
0 1
103 2
102 6
100 1
2
0 45 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__716 
6
2 1
1 0
0 1
103 2
102 6
100 1
2
0 45 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__717 
5
2 1
1 0
0 1
103 2
102 8
3
0 46 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__718 
6
2 1
1 0
0 1
103 2
102 8
100 1
2
0 46 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__719 
6
2 1
1 0
0 1
103 2
102 8
100 1
2
0 46 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__72 
5
2 0
1 0
0 1
103 7
102 1
3
0 67 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__720 
5
2 1
1 0
0 1
103 2
102 12
3
0 47 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__721 
6
2 1
1 0
0 1
103 2
102 12
100 1
2
0 47 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__722 
6
2 1
1 0
0 1
103 2
102 12
100 1
2
0 47 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__723 
5
2 1
1 0
0 1
103 2
102 2
3
0 44 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__724 
6
2 1
1 0
0 1
103 2
102 2
100 1
2
0 44 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__725 
6
2 1
1 0
0 1
103 2
102 2
100 1
2
0 44 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__726 
5
2 1
1 0
0 1
103 2
102 4
3
0 16 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__727 
6
2 1
1 0
0 1
103 2
102 4
100 1
2
0 16 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__728 
6
2 1
1 0
0 1
103 2
102 4
100 1
2
0 16 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__729 
5
2 1
1 0
0 1
103 3
102 0
3
0 17 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__73 
6
2 0
1 0
0 1
103 7
102 1
100 1
2
0 67 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__730 
6
2 1
1 0
0 1
103 3
102 0
100 1
2
0 17 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__731 
6
2 1
1 0
0 1
103 3
102 0
100 1
2
0 17 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__732 
5
2 1
1 0
0 1
103 3
102 5
3
0 49 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__733 
6
2 1
1 0
0 1
103 3
102 5
100 1
2
0 49 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__734 
6
2 1
1 0
0 1
103 3
102 5
100 1
2
0 49 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__735 
5
2 1
1 0
0 1
103 3
102 6
3
0 50 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__736 
6
2 1
1 0
0 1
103 3
102 6
100 1
2
0 50 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__737 
6
2 1
1 0
0 1
103 3
102 6
100 1
2
0 50 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__738 
5
2 1
1 0
0 1
103 3
102 8
3
0 51 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__739 
6
2 1
1 0
0 1
103 3
102 8
100 1
2
0 51 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__74 
6
2 0
1 0
0 1
103 7
102 1
100 1
2
0 67 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__740 
6
2 1
1 0
0 1
103 3
102 8
100 1
2
0 51 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__741 
5
2 1
1 0
0 1
103 3
102 10
3
0 52 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__742 
6
2 1
1 0
0 1
103 3
102 10
100 1
2
0 52 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__743 
6
2 1
1 0
0 1
103 3
102 10
100 1
2
0 52 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__744 
5
2 1
1 0
0 1
103 3
102 11
3
0 53 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__745 
6
2 1
1 0
0 1
103 3
102 11
100 1
2
0 53 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__746 
6
2 1
1 0
0 1
103 3
102 11
100 1
2
0 53 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__747 
5
2 1
1 0
0 1
103 3
102 12
3
0 54 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__748 
6
2 1
1 0
0 1
103 3
102 12
100 1
2
0 54 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__749 
6
2 1
1 0
0 1
103 3
102 12
100 1
2
0 54 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__75 
5
2 0
1 0
0 1
103 8
102 0
3
0 73 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__750 
5
2 1
1 0
0 1
103 3
102 2
3
0 48 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__751 
6
2 1
1 0
0 1
103 3
102 2
100 1
2
0 48 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__752 
6
2 1
1 0
0 1
103 3
102 2
100 1
2
0 48 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__753 
5
2 1
1 0
0 1
103 3
102 4
3
0 18 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__754 
6
2 1
1 0
0 1
103 3
102 4
100 1
2
0 18 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__755 
6
2 1
1 0
0 1
103 3
102 4
100 1
2
0 18 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__756 
5
2 1
1 0
0 1
103 4
102 0
3
0 19 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__757 
6
2 1
1 0
0 1
103 4
102 0
100 1
2
0 19 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__758 
6
2 1
1 0
0 1
103 4
102 0
100 1
2
0 19 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__759 
5
2 1
1 0
0 1
103 4
102 8
3
0 56 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__76 
6
2 0
1 0
0 1
103 8
102 0
100 1
2
0 73 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__760 
6
2 1
1 0
0 1
103 4
102 8
100 1
2
0 56 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__761 
6
2 1
1 0
0 1
103 4
102 8
100 1
2
0 56 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__762 
5
2 1
1 0
0 1
103 4
102 10
3
0 57 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__763 
6
2 1
1 0
0 1
103 4
102 10
100 1
2
0 57 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__764 
6
2 1
1 0
0 1
103 4
102 10
100 1
2
0 57 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__765 
5
2 1
1 0
0 1
103 4
102 2
3
0 55 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__766 
6
2 1
1 0
0 1
103 4
102 2
100 1
2
0 55 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__767 
6
2 1
1 0
0 1
103 4
102 2
100 1
2
0 55 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__768 
5
2 1
1 0
0 1
103 4
102 4
3
0 20 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__769 
6
2 1
1 0
0 1
103 4
102 4
100 1
2
0 20 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__77 
6
2 0
1 0
0 1
103 8
102 0
100 1
2
0 73 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__770 
6
2 1
1 0
0 1
103 4
102 4
100 1
2
0 20 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__771 
5
2 3
1 0
0 1
103 0
102 0
3
0 30 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__772 
6
2 3
1 0
0 1
103 0
102 0
100 1
2
0 30 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__773 
6
2 3
1 0
0 1
103 0
102 0
100 1
2
0 30 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__774 
5
2 3
1 0
0 1
103 0
102 6
3
0 58 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__775 
6
2 3
1 0
0 1
103 0
102 6
100 1
2
0 58 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__776 
6
2 3
1 0
0 1
103 0
102 6
100 1
2
0 58 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__777 
5
2 3
1 0
0 1
103 0
102 12
3
0 59 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__778 
6
2 3
1 0
0 1
103 0
102 12
100 1
2
0 59 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__779 
6
2 3
1 0
0 1
103 0
102 12
100 1
2
0 59 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__78 
5
2 0
1 0
0 1
103 8
102 5
3
0 74 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__780 
5
2 3
1 0
0 1
103 0
102 4
3
0 31 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__781 
6
2 3
1 0
0 1
103 0
102 4
100 1
2
0 31 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__782 
6
2 3
1 0
0 1
103 0
102 4
100 1
2
0 31 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__783 
5
2 3
1 0
0 1
103 5
102 0
3
0 32 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__784 
6
2 3
1 0
0 1
103 5
102 0
100 1
2
0 32 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__785 
6
2 3
1 0
0 1
103 5
102 0
100 1
2
0 32 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__786 
5
2 3
1 0
0 1
103 5
102 6
3
0 62 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__787 
6
2 3
1 0
0 1
103 5
102 6
100 1
2
0 62 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__788 
6
2 3
1 0
0 1
103 5
102 6
100 1
2
0 62 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__789 
5
2 3
1 0
0 1
103 5
102 7
3
0 63 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__79 
6
2 0
1 0
0 1
103 8
102 5
100 1
2
0 74 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__790 
6
2 3
1 0
0 1
103 5
102 7
100 1
2
0 63 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__791 
6
2 3
1 0
0 1
103 5
102 7
100 1
2
0 63 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__792 
5
2 3
1 0
0 1
103 5
102 8
3
0 64 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__793 
6
2 3
1 0
0 1
103 5
102 8
100 1
2
0 64 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__794 
6
2 3
1 0
0 1
103 5
102 8
100 1
2
0 64 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__795 
5
2 3
1 0
0 1
103 5
102 10
3
0 65 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__796 
6
2 3
1 0
0 1
103 5
102 10
100 1
2
0 65 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__797 
6
2 3
1 0
0 1
103 5
102 10
100 1
2
0 65 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__798 
5
2 3
1 0
0 1
103 5
102 12
3
0 66 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__799 
6
2 3
1 0
0 1
103 5
102 12
100 1
2
0 66 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__8 
6
2 0
1 0
0 1
103 0
102 7
100 1
2
0 11 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__80 
6
2 0
1 0
0 1
103 8
102 5
100 1
2
0 74 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__800 
6
2 3
1 0
0 1
103 5
102 12
100 1
2
0 66 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__801 
5
2 3
1 0
0 1
103 5
102 2
3
0 60 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__802 
6
2 3
1 0
0 1
103 5
102 2
100 1
2
0 60 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__803 
6
2 3
1 0
0 1
103 5
102 2
100 1
2
0 60 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__804 
5
2 3
1 0
0 1
103 5
102 3
3
0 61 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__805 
6
2 3
1 0
0 1
103 5
102 3
100 1
2
0 61 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__806 
6
2 3
1 0
0 1
103 5
102 3
100 1
2
0 61 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__807 
5
2 3
1 0
0 1
103 5
102 4
3
0 33 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__808 
6
2 3
1 0
0 1
103 5
102 4
100 1
2
0 33 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__809 
6
2 3
1 0
0 1
103 5
102 4
100 1
2
0 33 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__81 
5
2 0
1 0
0 1
103 8
102 6
3
0 75 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__810 
5
2 3
1 0
0 1
103 6
102 0
3
0 34 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__811 
6
2 3
1 0
0 1
103 6
102 0
100 1
2
0 34 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__812 
6
2 3
1 0
0 1
103 6
102 0
100 1
2
0 34 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__813 
5
2 3
1 0
0 1
103 6
102 8
3
0 68 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__814 
6
2 3
1 0
0 1
103 6
102 8
100 1
2
0 68 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__815 
6
2 3
1 0
0 1
103 6
102 8
100 1
2
0 68 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__816 
5
2 3
1 0
0 1
103 6
102 10
3
0 69 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__817 
6
2 3
1 0
0 1
103 6
102 10
100 1
2
0 69 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__818 
6
2 3
1 0
0 1
103 6
102 10
100 1
2
0 69 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__819 
5
2 3
1 0
0 1
103 6
102 12
3
0 70 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__82 
6
2 0
1 0
0 1
103 8
102 6
100 1
2
0 75 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__820 
6
2 3
1 0
0 1
103 6
102 12
100 1
2
0 70 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__821 
6
2 3
1 0
0 1
103 6
102 12
100 1
2
0 70 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__822 
5
2 3
1 0
0 1
103 6
102 2
3
0 67 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__823 
6
2 3
1 0
0 1
103 6
102 2
100 1
2
0 67 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__824 
6
2 3
1 0
0 1
103 6
102 2
100 1
2
0 67 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__825 
5
2 3
1 0
0 1
103 7
102 0
3
0 35 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__826 
6
2 3
1 0
0 1
103 7
102 0
100 1
2
0 35 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__827 
6
2 3
1 0
0 1
103 7
102 0
100 1
2
0 35 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__828 
5
2 3
1 0
0 1
103 7
102 5
3
0 73 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__829 
6
2 3
1 0
0 1
103 7
102 5
100 1
2
0 73 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__83 
6
2 0
1 0
0 1
103 8
102 6
100 1
2
0 75 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__830 
6
2 3
1 0
0 1
103 7
102 5
100 1
2
0 73 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__831 
5
2 3
1 0
0 1
103 7
102 6
3
0 74 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__832 
6
2 3
1 0
0 1
103 7
102 6
100 1
2
0 74 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__833 
6
2 3
1 0
0 1
103 7
102 6
100 1
2
0 74 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__834 
5
2 3
1 0
0 1
103 7
102 7
3
0 75 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__835 
6
2 3
1 0
0 1
103 7
102 7
100 1
2
0 75 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__836 
6
2 3
1 0
0 1
103 7
102 7
100 1
2
0 75 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__837 
5
2 3
1 0
0 1
103 7
102 8
3
0 76 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__838 
6
2 3
1 0
0 1
103 7
102 8
100 1
2
0 76 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__839 
6
2 3
1 0
0 1
103 7
102 8
100 1
2
0 76 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__84 
5
2 0
1 0
0 1
103 8
102 7
3
0 76 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__840 
5
2 3
1 0
0 1
103 7
102 10
3
0 77 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__841 
6
2 3
1 0
0 1
103 7
102 10
100 1
2
0 77 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__842 
6
2 3
1 0
0 1
103 7
102 10
100 1
2
0 77 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__843 
5
2 3
1 0
0 1
103 7
102 11
3
0 78 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__844 
6
2 3
1 0
0 1
103 7
102 11
100 1
2
0 78 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__845 
6
2 3
1 0
0 1
103 7
102 11
100 1
2
0 78 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__846 
5
2 3
1 0
0 1
103 7
102 12
3
0 79 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__847 
6
2 3
1 0
0 1
103 7
102 12
100 1
2
0 79 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__848 
6
2 3
1 0
0 1
103 7
102 12
100 1
2
0 79 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__849 
5
2 3
1 0
0 1
103 7
102 2
3
0 71 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__85 
6
2 0
1 0
0 1
103 8
102 7
100 1
2
0 76 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__850 
6
2 3
1 0
0 1
103 7
102 2
100 1
2
0 71 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__851 
6
2 3
1 0
0 1
103 7
102 2
100 1
2
0 71 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__852 
5
2 3
1 0
0 1
103 7
102 3
3
0 72 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__853 
6
2 3
1 0
0 1
103 7
102 3
100 1
2
0 72 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__854 
6
2 3
1 0
0 1
103 7
102 3
100 1
2
0 72 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__855 
5
2 3
1 0
0 1
103 7
102 4
3
0 36 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__856 
6
2 3
1 0
0 1
103 7
102 4
100 1
2
0 36 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__857 
6
2 3
1 0
0 1
103 7
102 4
100 1
2
0 36 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__858 
5
2 3
1 0
0 1
103 8
102 10
3
0 80 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__859 
6
2 3
1 0
0 1
103 8
102 10
100 1
2
0 80 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__86 
6
2 0
1 0
0 1
103 8
102 7
100 1
2
0 76 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__860 
6
2 3
1 0
0 1
103 8
102 10
100 1
2
0 80 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__861 
5
2 3
1 0
0 1
103 8
102 4
3
0 37 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__862 
6
2 3
1 0
0 1
103 8
102 4
100 1
2
0 37 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__863 
6
2 3
1 0
0 1
103 8
102 4
100 1
2
0 37 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__864 
5
2 3
1 0
0 1
103 9
102 0
3
0 38 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__865 
6
2 3
1 0
0 1
103 9
102 0
100 1
2
0 38 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__866 
6
2 3
1 0
0 1
103 9
102 0
100 1
2
0 38 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__867 
5
2 3
1 0
0 1
103 9
102 5
3
0 83 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__868 
6
2 3
1 0
0 1
103 9
102 5
100 1
2
0 83 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__869 
6
2 3
1 0
0 1
103 9
102 5
100 1
2
0 83 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__87 
5
2 0
1 0
0 1
103 8
102 9
3
0 77 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__870 
5
2 3
1 0
0 1
103 9
102 6
3
0 84 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__871 
6
2 3
1 0
0 1
103 9
102 6
100 1
2
0 84 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__872 
6
2 3
1 0
0 1
103 9
102 6
100 1
2
0 84 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__873 
5
2 3
1 0
0 1
103 9
102 7
3
0 85 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__874 
6
2 3
1 0
0 1
103 9
102 7
100 1
2
0 85 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__875 
6
2 3
1 0
0 1
103 9
102 7
100 1
2
0 85 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__876 
5
2 3
1 0
0 1
103 9
102 8
3
0 86 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__877 
6
2 3
1 0
0 1
103 9
102 8
100 1
2
0 86 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__878 
6
2 3
1 0
0 1
103 9
102 8
100 1
2
0 86 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__879 
5
2 3
1 0
0 1
103 9
102 10
3
0 87 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__88 
6
2 0
1 0
0 1
103 8
102 9
100 1
2
0 77 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__880 
6
2 3
1 0
0 1
103 9
102 10
100 1
2
0 87 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__881 
6
2 3
1 0
0 1
103 9
102 10
100 1
2
0 87 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__882 
5
2 3
1 0
0 1
103 9
102 11
3
0 88 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__883 
6
2 3
1 0
0 1
103 9
102 11
100 1
2
0 88 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__884 
6
2 3
1 0
0 1
103 9
102 11
100 1
2
0 88 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__885 
5
2 3
1 0
0 1
103 9
102 12
3
0 89 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__886 
6
2 3
1 0
0 1
103 9
102 12
100 1
2
0 89 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__887 
6
2 3
1 0
0 1
103 9
102 12
100 1
2
0 89 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__888 
5
2 3
1 0
0 1
103 9
102 2
3
0 81 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__889 
6
2 3
1 0
0 1
103 9
102 2
100 1
2
0 81 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__89 
6
2 0
1 0
0 1
103 8
102 9
100 1
2
0 77 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__890 
6
2 3
1 0
0 1
103 9
102 2
100 1
2
0 81 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__891 
5
2 3
1 0
0 1
103 9
102 3
3
0 82 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__892 
6
2 3
1 0
0 1
103 9
102 3
100 1
2
0 82 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__893 
6
2 3
1 0
0 1
103 9
102 3
100 1
2
0 82 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__894 
5
2 3
1 0
0 1
103 9
102 4
3
0 39 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__895 
6
2 3
1 0
0 1
103 9
102 4
100 1
2
0 39 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__896 
6
2 3
1 0
0 1
103 9
102 4
100 1
2
0 39 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__897 
5
2 3
1 0
0 1
103 10
102 0
3
0 40 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__898 
6
2 3
1 0
0 1
103 10
102 0
100 1
2
0 40 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__899 
6
2 3
1 0
0 1
103 10
102 0
100 1
2
0 40 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__9 
5
2 0
1 0
0 1
103 0
102 8
3
0 12 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__90 
5
2 0
1 0
0 1
103 8
102 10
3
0 78 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__900 
5
2 3
1 0
0 1
103 10
102 8
3
0 91 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__901 
6
2 3
1 0
0 1
103 10
102 8
100 1
2
0 91 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__902 
6
2 3
1 0
0 1
103 10
102 8
100 1
2
0 91 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__903 
5
2 3
1 0
0 1
103 10
102 12
3
0 92 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__904 
6
2 3
1 0
0 1
103 10
102 12
100 1
2
0 92 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__905 
6
2 3
1 0
0 1
103 10
102 12
100 1
2
0 92 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__906 
5
2 3
1 0
0 1
103 10
102 2
3
0 90 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__907 
6
2 3
1 0
0 1
103 10
102 2
100 1
2
0 90 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__908 
6
2 3
1 0
0 1
103 10
102 2
100 1
2
0 90 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__909 
5
2 3
1 0
0 1
103 10
102 4
3
0 41 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__91 
6
2 0
1 0
0 1
103 8
102 10
100 1
2
0 78 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__910 
6
2 3
1 0
0 1
103 10
102 4
100 1
2
0 41 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__911 
6
2 3
1 0
0 1
103 10
102 4
100 1
2
0 41 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__912 
5
2 3
1 0
0 1
103 11
102 0
3
0 42 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__913 
6
2 3
1 0
0 1
103 11
102 0
100 1
2
0 42 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__914 
6
2 3
1 0
0 1
103 11
102 0
100 1
2
0 42 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__915 
5
2 3
1 0
0 1
103 11
102 5
3
0 94 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__916 
6
2 3
1 0
0 1
103 11
102 5
100 1
2
0 94 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__917 
6
2 3
1 0
0 1
103 11
102 5
100 1
2
0 94 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__918 
5
2 3
1 0
0 1
103 11
102 6
3
0 95 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__919 
6
2 3
1 0
0 1
103 11
102 6
100 1
2
0 95 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__92 
6
2 0
1 0
0 1
103 8
102 10
100 1
2
0 78 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__920 
6
2 3
1 0
0 1
103 11
102 6
100 1
2
0 95 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__921 
5
2 3
1 0
0 1
103 11
102 8
3
0 96 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__922 
6
2 3
1 0
0 1
103 11
102 8
100 1
2
0 96 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__923 
6
2 3
1 0
0 1
103 11
102 8
100 1
2
0 96 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__924 
5
2 3
1 0
0 1
103 11
102 9
3
0 97 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__925 
6
2 3
1 0
0 1
103 11
102 9
100 1
2
0 97 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__926 
6
2 3
1 0
0 1
103 11
102 9
100 1
2
0 97 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__927 
5
2 3
1 0
0 1
103 11
102 10
3
0 98 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__928 
6
2 3
1 0
0 1
103 11
102 10
100 1
2
0 98 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__929 
6
2 3
1 0
0 1
103 11
102 10
100 1
2
0 98 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__93 
5
2 0
1 0
0 1
103 8
102 11
3
0 79 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__930 
5
2 3
1 0
0 1
103 11
102 12
3
0 99 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__931 
6
2 3
1 0
0 1
103 11
102 12
100 1
2
0 99 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__932 
6
2 3
1 0
0 1
103 11
102 12
100 1
2
0 99 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__933 
5
2 3
1 0
0 1
103 11
102 2
3
0 93 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__934 
6
2 3
1 0
0 1
103 11
102 2
100 1
2
0 93 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__935 
6
2 3
1 0
0 1
103 11
102 2
100 1
2
0 93 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__936 
5
2 3
1 0
0 1
103 11
102 4
3
0 43 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__937 
6
2 3
1 0
0 1
103 11
102 4
100 1
2
0 43 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__938 
6
2 3
1 0
0 1
103 11
102 4
100 1
2
0 43 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__939 
5
2 3
1 0
0 1
103 12
102 6
3
0 45 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__94 
6
2 0
1 0
0 1
103 8
102 11
100 1
2
0 79 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__940 
6
2 3
1 0
0 1
103 12
102 6
100 1
2
0 45 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__941 
6
2 3
1 0
0 1
103 12
102 6
100 1
2
0 45 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__942 
5
2 3
1 0
0 1
103 12
102 8
3
0 46 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__943 
6
2 3
1 0
0 1
103 12
102 8
100 1
2
0 46 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__944 
6
2 3
1 0
0 1
103 12
102 8
100 1
2
0 46 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__945 
5
2 3
1 0
0 1
103 12
102 12
3
0 47 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__946 
6
2 3
1 0
0 1
103 12
102 12
100 1
2
0 47 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__947 
6
2 3
1 0
0 1
103 12
102 12
100 1
2
0 47 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__948 
5
2 3
1 0
0 1
103 12
102 2
3
0 44 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__949 
6
2 3
1 0
0 1
103 12
102 2
100 1
2
0 44 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__95 
6
2 0
1 0
0 1
103 8
102 11
100 1
2
0 79 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__950 
6
2 3
1 0
0 1
103 12
102 2
100 1
2
0 44 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__951 
5
2 3
1 0
0 1
103 12
102 4
3
0 16 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__952 
6
2 3
1 0
0 1
103 12
102 4
100 1
2
0 16 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__953 
6
2 3
1 0
0 1
103 12
102 4
100 1
2
0 16 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__954 
5
2 3
1 0
0 1
103 1
102 0
3
0 17 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__955 
6
2 3
1 0
0 1
103 1
102 0
100 1
2
0 17 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__956 
6
2 3
1 0
0 1
103 1
102 0
100 1
2
0 17 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__957 
5
2 3
1 0
0 1
103 1
102 5
3
0 49 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__958 
6
2 3
1 0
0 1
103 1
102 5
100 1
2
0 49 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__959 
6
2 3
1 0
0 1
103 1
102 5
100 1
2
0 49 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__96 
5
2 0
1 0
0 1
103 8
102 1
3
0 71 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__960 
5
2 3
1 0
0 1
103 1
102 6
3
0 50 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__961 
6
2 3
1 0
0 1
103 1
102 6
100 1
2
0 50 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__962 
6
2 3
1 0
0 1
103 1
102 6
100 1
2
0 50 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__963 
5
2 3
1 0
0 1
103 1
102 8
3
0 51 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__964 
6
2 3
1 0
0 1
103 1
102 8
100 1
2
0 51 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__965 
6
2 3
1 0
0 1
103 1
102 8
100 1
2
0 51 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__966 
5
2 3
1 0
0 1
103 1
102 10
3
0 52 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__967 
6
2 3
1 0
0 1
103 1
102 10
100 1
2
0 52 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__968 
6
2 3
1 0
0 1
103 1
102 10
100 1
2
0 52 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__969 
5
2 3
1 0
0 1
103 1
102 11
3
0 53 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__97 
6
2 0
1 0
0 1
103 8
102 1
100 1
2
0 71 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__970 
6
2 3
1 0
0 1
103 1
102 11
100 1
2
0 53 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__971 
6
2 3
1 0
0 1
103 1
102 11
100 1
2
0 53 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__972 
5
2 3
1 0
0 1
103 1
102 12
3
0 54 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__973 
6
2 3
1 0
0 1
103 1
102 12
100 1
2
0 54 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__974 
6
2 3
1 0
0 1
103 1
102 12
100 1
2
0 54 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__975 
5
2 3
1 0
0 1
103 1
102 2
3
0 48 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__976 
6
2 3
1 0
0 1
103 1
102 2
100 1
2
0 48 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__977 
6
2 3
1 0
0 1
103 1
102 2
100 1
2
0 48 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__978 
5
2 3
1 0
0 1
103 1
102 4
3
0 18 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__979 
6
2 3
1 0
0 1
103 1
102 4
100 1
2
0 18 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__98 
6
2 0
1 0
0 1
103 8
102 1
100 1
2
0 71 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__980 
6
2 3
1 0
0 1
103 1
102 4
100 1
2
0 18 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__981 
5
2 3
1 0
0 1
103 2
102 0
3
0 19 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__982 
6
2 3
1 0
0 1
103 2
102 0
100 1
2
0 19 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__983 
6
2 3
1 0
0 1
103 2
102 0
100 1
2
0 19 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__984 
5
2 3
1 0
0 1
103 2
102 8
3
0 56 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__985 
6
2 3
1 0
0 1
103 2
102 8
100 1
2
0 56 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__986 
6
2 3
1 0
0 1
103 2
102 8
100 1
2
0 56 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__987 
5
2 3
1 0
0 1
103 2
102 10
3
0 57 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__988 
6
2 3
1 0
0 1
103 2
102 10
100 1
2
0 57 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__989 
6
2 3
1 0
0 1
103 2
102 10
100 1
2
0 57 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__99 
5
2 0
1 0
0 1
103 8
102 2
3
0 72 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__990 
5
2 3
1 0
0 1
103 2
102 2
3
0 55 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__991 
6
2 3
1 0
0 1
103 2
102 2
100 1
2
0 55 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__992 
6
2 3
1 0
0 1
103 2
102 2
100 1
2
0 55 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__993 
5
2 3
1 0
0 1
103 2
102 4
3
0 20 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__994 
6
2 3
1 0
0 1
103 2
102 4
100 1
2
0 20 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__995 
6
2 3
1 0
0 1
103 2
102 4
100 1
2
0 20 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__996 
5
2 3
1 0
0 1
103 3
102 0
3
0 5 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
destroy_block__997 
6
2 3
1 0
0 1
103 3
102 0
100 1
2
0 5 1 0
0 101 0 1
1
end_operator
begin_operator
destroy_block__998 
6
2 3
1 0
0 1
103 3
102 0
100 1
2
0 5 1 0
0 101 1 2
1
end_operator
begin_operator
destroy_block__999 
5
2 3
1 0
0 1
103 3
102 5
3
0 23 1 0
0 100 0 1
0 101 0 1
1
end_operator
begin_operator
look_ahead__1 
0
1
0 0 1 0
1
end_operator
begin_operator
look_down__0 
0
1
0 0 0 1
1
end_operator
begin_operator
move_forward__0 
3
2 0
103 0
9 0
1
0 102 5 6
1
end_operator
begin_operator
move_forward__1 
3
2 0
103 0
10 0
1
0 102 6 7
1
end_operator
begin_operator
move_forward__10 
3
2 0
103 5
58 0
1
0 102 5 6
1
end_operator
begin_operator
move_forward__100 
3
2 2
103 6
62 0
1
0 102 7 6
1
end_operator
begin_operator
move_forward__101 
3
2 2
103 6
63 0
1
0 102 8 7
1
end_operator
begin_operator
move_forward__102 
3
2 2
103 6
64 0
1
0 102 9 8
1
end_operator
begin_operator
move_forward__103 
3
2 2
103 6
65 0
1
0 102 11 10
1
end_operator
begin_operator
move_forward__104 
3
2 2
103 6
66 0
1
0 102 1 12
1
end_operator
begin_operator
move_forward__105 
3
2 2
103 6
60 0
1
0 102 3 2
1
end_operator
begin_operator
move_forward__106 
3
2 2
103 6
61 0
1
0 102 4 3
1
end_operator
begin_operator
move_forward__107 
3
2 2
103 7
34 0
1
0 102 5 0
1
end_operator
begin_operator
move_forward__108 
3
2 2
103 7
68 0
1
0 102 9 8
1
end_operator
begin_operator
move_forward__109 
3
2 2
103 7
69 0
1
0 102 11 10
1
end_operator
begin_operator
move_forward__11 
3
2 0
103 5
59 0
1
0 102 11 12
1
end_operator
begin_operator
move_forward__110 
3
2 2
103 7
70 0
1
0 102 1 12
1
end_operator
begin_operator
move_forward__111 
3
2 2
103 7
67 0
1
0 102 3 2
1
end_operator
begin_operator
move_forward__112 
3
2 2
103 8
35 0
1
0 102 5 0
1
end_operator
begin_operator
move_forward__113 
3
2 2
103 8
73 0
1
0 102 6 5
1
end_operator
begin_operator
move_forward__114 
3
2 2
103 8
74 0
1
0 102 7 6
1
end_operator
begin_operator
move_forward__115 
3
2 2
103 8
75 0
1
0 102 8 7
1
end_operator
begin_operator
move_forward__116 
3
2 2
103 8
76 0
1
0 102 9 8
1
end_operator
begin_operator
move_forward__117 
3
2 2
103 8
77 0
1
0 102 11 10
1
end_operator
begin_operator
move_forward__118 
3
2 2
103 8
78 0
1
0 102 12 11
1
end_operator
begin_operator
move_forward__119 
3
2 2
103 8
79 0
1
0 102 1 12
1
end_operator
begin_operator
move_forward__12 
3
2 0
103 5
31 0
1
0 102 3 4
1
end_operator
begin_operator
move_forward__120 
3
2 2
103 8
71 0
1
0 102 3 2
1
end_operator
begin_operator
move_forward__121 
3
2 2
103 8
72 0
1
0 102 4 3
1
end_operator
begin_operator
move_forward__122 
3
2 2
103 9
80 0
1
0 102 11 10
1
end_operator
begin_operator
move_forward__123 
3
2 2
103 10
38 0
1
0 102 5 0
1
end_operator
begin_operator
move_forward__124 
3
2 2
103 10
83 0
1
0 102 6 5
1
end_operator
begin_operator
move_forward__125 
3
2 2
103 10
84 0
1
0 102 7 6
1
end_operator
begin_operator
move_forward__126 
3
2 2
103 10
85 0
1
0 102 8 7
1
end_operator
begin_operator
move_forward__127 
3
2 2
103 10
86 0
1
0 102 9 8
1
end_operator
begin_operator
move_forward__128 
3
2 2
103 10
87 0
1
0 102 11 10
1
end_operator
begin_operator
move_forward__129 
3
2 2
103 10
88 0
1
0 102 12 11
1
end_operator
begin_operator
move_forward__13 
3
2 0
103 6
62 0
1
0 102 5 6
1
end_operator
begin_operator
move_forward__130 
3
2 2
103 10
89 0
1
0 102 1 12
1
end_operator
begin_operator
move_forward__131 
3
2 2
103 10
81 0
1
0 102 3 2
1
end_operator
begin_operator
move_forward__132 
3
2 2
103 10
82 0
1
0 102 4 3
1
end_operator
begin_operator
move_forward__133 
3
2 2
103 11
40 0
1
0 102 5 0
1
end_operator
begin_operator
move_forward__134 
3
2 2
103 11
91 0
1
0 102 9 8
1
end_operator
begin_operator
move_forward__135 
3
2 2
103 11
92 0
1
0 102 1 12
1
end_operator
begin_operator
move_forward__136 
3
2 2
103 11
90 0
1
0 102 3 2
1
end_operator
begin_operator
move_forward__137 
3
2 2
103 12
42 0
1
0 102 5 0
1
end_operator
begin_operator
move_forward__138 
3
2 2
103 12
94 0
1
0 102 6 5
1
end_operator
begin_operator
move_forward__139 
3
2 2
103 12
95 0
1
0 102 7 6
1
end_operator
begin_operator
move_forward__14 
3
2 0
103 6
63 0
1
0 102 6 7
1
end_operator
begin_operator
move_forward__140 
3
2 2
103 12
96 0
1
0 102 9 8
1
end_operator
begin_operator
move_forward__141 
3
2 2
103 12
97 0
1
0 102 10 9
1
end_operator
begin_operator
move_forward__142 
3
2 2
103 12
98 0
1
0 102 11 10
1
end_operator
begin_operator
move_forward__143 
3
2 2
103 12
99 0
1
0 102 1 12
1
end_operator
begin_operator
move_forward__144 
3
2 2
103 12
93 0
1
0 102 3 2
1
end_operator
begin_operator
move_forward__145 
3
2 2
103 1
45 0
1
0 102 7 6
1
end_operator
begin_operator
move_forward__146 
3
2 2
103 1
46 0
1
0 102 9 8
1
end_operator
begin_operator
move_forward__147 
3
2 2
103 1
47 0
1
0 102 1 12
1
end_operator
begin_operator
move_forward__148 
3
2 2
103 1
44 0
1
0 102 3 2
1
end_operator
begin_operator
move_forward__149 
3
2 2
103 2
17 0
1
0 102 5 0
1
end_operator
begin_operator
move_forward__15 
3
2 0
103 6
64 0
1
0 102 7 8
1
end_operator
begin_operator
move_forward__150 
3
2 2
103 2
49 0
1
0 102 6 5
1
end_operator
begin_operator
move_forward__151 
3
2 2
103 2
50 0
1
0 102 7 6
1
end_operator
begin_operator
move_forward__152 
3
2 2
103 2
51 0
1
0 102 9 8
1
end_operator
begin_operator
move_forward__153 
3
2 2
103 2
52 0
1
0 102 11 10
1
end_operator
begin_operator
move_forward__154 
3
2 2
103 2
53 0
1
0 102 12 11
1
end_operator
begin_operator
move_forward__155 
3
2 2
103 2
54 0
1
0 102 1 12
1
end_operator
begin_operator
move_forward__156 
3
2 2
103 2
48 0
1
0 102 3 2
1
end_operator
begin_operator
move_forward__157 
3
2 2
103 3
19 0
1
0 102 5 0
1
end_operator
begin_operator
move_forward__158 
3
2 2
103 3
56 0
1
0 102 9 8
1
end_operator
begin_operator
move_forward__159 
3
2 2
103 3
57 0
1
0 102 11 10
1
end_operator
begin_operator
move_forward__16 
3
2 0
103 6
65 0
1
0 102 9 10
1
end_operator
begin_operator
move_forward__160 
3
2 2
103 3
55 0
1
0 102 3 2
1
end_operator
begin_operator
move_forward__161 
3
2 2
103 4
5 0
1
0 102 5 0
1
end_operator
begin_operator
move_forward__162 
3
2 2
103 4
23 0
1
0 102 6 5
1
end_operator
begin_operator
move_forward__163 
3
2 2
103 4
24 0
1
0 102 7 6
1
end_operator
begin_operator
move_forward__164 
3
2 2
103 4
25 0
1
0 102 9 8
1
end_operator
begin_operator
move_forward__165 
3
2 2
103 4
26 0
1
0 102 10 9
1
end_operator
begin_operator
move_forward__166 
3
2 2
103 4
27 0
1
0 102 11 10
1
end_operator
begin_operator
move_forward__167 
3
2 2
103 4
28 0
1
0 102 12 11
1
end_operator
begin_operator
move_forward__168 
3
2 2
103 4
29 0
1
0 102 1 12
1
end_operator
begin_operator
move_forward__169 
3
2 2
103 4
21 0
1
0 102 2 1
1
end_operator
begin_operator
move_forward__17 
3
2 0
103 6
66 0
1
0 102 11 12
1
end_operator
begin_operator
move_forward__170 
3
2 2
103 4
22 0
1
0 102 3 2
1
end_operator
begin_operator
move_forward__171 
3
2 1
102 0
3 0
1
0 103 5 0
1
end_operator
begin_operator
move_forward__172 
3
2 1
102 6
9 0
1
0 103 5 0
1
end_operator
begin_operator
move_forward__173 
3
2 1
102 7
10 0
1
0 103 5 0
1
end_operator
begin_operator
move_forward__174 
3
2 1
102 8
11 0
1
0 103 5 0
1
end_operator
begin_operator
move_forward__175 
3
2 1
102 9
12 0
1
0 103 5 0
1
end_operator
begin_operator
move_forward__176 
3
2 1
102 10
13 0
1
0 103 5 0
1
end_operator
begin_operator
move_forward__177 
3
2 1
102 11
14 0
1
0 103 5 0
1
end_operator
begin_operator
move_forward__178 
3
2 1
102 12
15 0
1
0 103 5 0
1
end_operator
begin_operator
move_forward__179 
3
2 1
102 2
7 0
1
0 103 5 0
1
end_operator
begin_operator
move_forward__18 
3
2 0
103 6
60 0
1
0 102 1 2
1
end_operator
begin_operator
move_forward__180 
3
2 1
102 3
8 0
1
0 103 5 0
1
end_operator
begin_operator
move_forward__181 
3
2 1
102 4
4 0
1
0 103 5 0
1
end_operator
begin_operator
move_forward__182 
3
2 1
102 0
30 0
1
0 103 6 5
1
end_operator
begin_operator
move_forward__183 
3
2 1
102 6
58 0
1
0 103 6 5
1
end_operator
begin_operator
move_forward__184 
3
2 1
102 12
59 0
1
0 103 6 5
1
end_operator
begin_operator
move_forward__185 
3
2 1
102 4
31 0
1
0 103 6 5
1
end_operator
begin_operator
move_forward__186 
3
2 1
102 0
32 0
1
0 103 7 6
1
end_operator
begin_operator
move_forward__187 
3
2 1
102 6
62 0
1
0 103 7 6
1
end_operator
begin_operator
move_forward__188 
3
2 1
102 7
63 0
1
0 103 7 6
1
end_operator
begin_operator
move_forward__189 
3
2 1
102 8
64 0
1
0 103 7 6
1
end_operator
begin_operator
move_forward__19 
3
2 0
103 6
61 0
1
0 102 2 3
1
end_operator
begin_operator
move_forward__190 
3
2 1
102 10
65 0
1
0 103 7 6
1
end_operator
begin_operator
move_forward__191 
3
2 1
102 12
66 0
1
0 103 7 6
1
end_operator
begin_operator
move_forward__192 
3
2 1
102 2
60 0
1
0 103 7 6
1
end_operator
begin_operator
move_forward__193 
3
2 1
102 3
61 0
1
0 103 7 6
1
end_operator
begin_operator
move_forward__194 
3
2 1
102 4
33 0
1
0 103 7 6
1
end_operator
begin_operator
move_forward__195 
3
2 1
102 0
34 0
1
0 103 8 7
1
end_operator
begin_operator
move_forward__196 
3
2 1
102 8
68 0
1
0 103 8 7
1
end_operator
begin_operator
move_forward__197 
3
2 1
102 10
69 0
1
0 103 8 7
1
end_operator
begin_operator
move_forward__198 
3
2 1
102 12
70 0
1
0 103 8 7
1
end_operator
begin_operator
move_forward__199 
3
2 1
102 2
67 0
1
0 103 8 7
1
end_operator
begin_operator
move_forward__2 
3
2 0
103 0
11 0
1
0 102 7 8
1
end_operator
begin_operator
move_forward__20 
3
2 0
103 6
33 0
1
0 102 3 4
1
end_operator
begin_operator
move_forward__200 
3
2 1
102 0
35 0
1
0 103 9 8
1
end_operator
begin_operator
move_forward__201 
3
2 1
102 5
73 0
1
0 103 9 8
1
end_operator
begin_operator
move_forward__202 
3
2 1
102 6
74 0
1
0 103 9 8
1
end_operator
begin_operator
move_forward__203 
3
2 1
102 7
75 0
1
0 103 9 8
1
end_operator
begin_operator
move_forward__204 
3
2 1
102 8
76 0
1
0 103 9 8
1
end_operator
begin_operator
move_forward__205 
3
2 1
102 10
77 0
1
0 103 9 8
1
end_operator
begin_operator
move_forward__206 
3
2 1
102 11
78 0
1
0 103 9 8
1
end_operator
begin_operator
move_forward__207 
3
2 1
102 12
79 0
1
0 103 9 8
1
end_operator
begin_operator
move_forward__208 
3
2 1
102 2
71 0
1
0 103 9 8
1
end_operator
begin_operator
move_forward__209 
3
2 1
102 3
72 0
1
0 103 9 8
1
end_operator
begin_operator
move_forward__21 
3
2 0
103 7
68 0
1
0 102 7 8
1
end_operator
begin_operator
move_forward__210 
3
2 1
102 4
36 0
1
0 103 9 8
1
end_operator
begin_operator
move_forward__211 
3
2 1
102 10
80 0
1
0 103 10 9
1
end_operator
begin_operator
move_forward__212 
3
2 1
102 4
37 0
1
0 103 10 9
1
end_operator
begin_operator
move_forward__213 
3
2 1
102 0
38 0
1
0 103 11 10
1
end_operator
begin_operator
move_forward__214 
3
2 1
102 5
83 0
1
0 103 11 10
1
end_operator
begin_operator
move_forward__215 
3
2 1
102 6
84 0
1
0 103 11 10
1
end_operator
begin_operator
move_forward__216 
3
2 1
102 7
85 0
1
0 103 11 10
1
end_operator
begin_operator
move_forward__217 
3
2 1
102 8
86 0
1
0 103 11 10
1
end_operator
begin_operator
move_forward__218 
3
2 1
102 10
87 0
1
0 103 11 10
1
end_operator
begin_operator
move_forward__219 
3
2 1
102 11
88 0
1
0 103 11 10
1
end_operator
begin_operator
move_forward__22 
3
2 0
103 7
69 0
1
0 102 9 10
1
end_operator
begin_operator
move_forward__220 
3
2 1
102 12
89 0
1
0 103 11 10
1
end_operator
begin_operator
move_forward__221 
3
2 1
102 2
81 0
1
0 103 11 10
1
end_operator
begin_operator
move_forward__222 
3
2 1
102 3
82 0
1
0 103 11 10
1
end_operator
begin_operator
move_forward__223 
3
2 1
102 4
39 0
1
0 103 11 10
1
end_operator
begin_operator
move_forward__224 
3
2 1
102 0
40 0
1
0 103 12 11
1
end_operator
begin_operator
move_forward__225 
3
2 1
102 8
91 0
1
0 103 12 11
1
end_operator
begin_operator
move_forward__226 
3
2 1
102 12
92 0
1
0 103 12 11
1
end_operator
begin_operator
move_forward__227 
3
2 1
102 2
90 0
1
0 103 12 11
1
end_operator
begin_operator
move_forward__228 
3
2 1
102 4
41 0
1
0 103 12 11
1
end_operator
begin_operator
move_forward__229 
3
2 1
102 0
42 0
1
0 103 1 12
1
end_operator
begin_operator
move_forward__23 
3
2 0
103 7
70 0
1
0 102 11 12
1
end_operator
begin_operator
move_forward__230 
3
2 1
102 5
94 0
1
0 103 1 12
1
end_operator
begin_operator
move_forward__231 
3
2 1
102 6
95 0
1
0 103 1 12
1
end_operator
begin_operator
move_forward__232 
3
2 1
102 8
96 0
1
0 103 1 12
1
end_operator
begin_operator
move_forward__233 
3
2 1
102 9
97 0
1
0 103 1 12
1
end_operator
begin_operator
move_forward__234 
3
2 1
102 10
98 0
1
0 103 1 12
1
end_operator
begin_operator
move_forward__235 
3
2 1
102 12
99 0
1
0 103 1 12
1
end_operator
begin_operator
move_forward__236 
3
2 1
102 2
93 0
1
0 103 1 12
1
end_operator
begin_operator
move_forward__237 
3
2 1
102 4
43 0
1
0 103 1 12
1
end_operator
begin_operator
move_forward__238 
3
2 1
102 6
45 0
1
0 103 2 1
1
end_operator
begin_operator
move_forward__239 
3
2 1
102 8
46 0
1
0 103 2 1
1
end_operator
begin_operator
move_forward__24 
3
2 0
103 7
67 0
1
0 102 1 2
1
end_operator
begin_operator
move_forward__240 
3
2 1
102 12
47 0
1
0 103 2 1
1
end_operator
begin_operator
move_forward__241 
3
2 1
102 2
44 0
1
0 103 2 1
1
end_operator
begin_operator
move_forward__242 
3
2 1
102 4
16 0
1
0 103 2 1
1
end_operator
begin_operator
move_forward__243 
3
2 1
102 0
17 0
1
0 103 3 2
1
end_operator
begin_operator
move_forward__244 
3
2 1
102 5
49 0
1
0 103 3 2
1
end_operator
begin_operator
move_forward__245 
3
2 1
102 6
50 0
1
0 103 3 2
1
end_operator
begin_operator
move_forward__246 
3
2 1
102 8
51 0
1
0 103 3 2
1
end_operator
begin_operator
move_forward__247 
3
2 1
102 10
52 0
1
0 103 3 2
1
end_operator
begin_operator
move_forward__248 
3
2 1
102 11
53 0
1
0 103 3 2
1
end_operator
begin_operator
move_forward__249 
3
2 1
102 12
54 0
1
0 103 3 2
1
end_operator
begin_operator
move_forward__25 
3
2 0
103 8
73 0
1
0 102 0 5
1
end_operator
begin_operator
move_forward__250 
3
2 1
102 2
48 0
1
0 103 3 2
1
end_operator
begin_operator
move_forward__251 
3
2 1
102 4
18 0
1
0 103 3 2
1
end_operator
begin_operator
move_forward__252 
3
2 1
102 0
19 0
1
0 103 4 3
1
end_operator
begin_operator
move_forward__253 
3
2 1
102 8
56 0
1
0 103 4 3
1
end_operator
begin_operator
move_forward__254 
3
2 1
102 10
57 0
1
0 103 4 3
1
end_operator
begin_operator
move_forward__255 
3
2 1
102 2
55 0
1
0 103 4 3
1
end_operator
begin_operator
move_forward__256 
3
2 1
102 4
20 0
1
0 103 4 3
1
end_operator
begin_operator
move_forward__257 
3
2 3
102 0
30 0
1
0 103 0 5
1
end_operator
begin_operator
move_forward__258 
3
2 3
102 6
58 0
1
0 103 0 5
1
end_operator
begin_operator
move_forward__259 
3
2 3
102 12
59 0
1
0 103 0 5
1
end_operator
begin_operator
move_forward__26 
3
2 0
103 8
74 0
1
0 102 5 6
1
end_operator
begin_operator
move_forward__260 
3
2 3
102 4
31 0
1
0 103 0 5
1
end_operator
begin_operator
move_forward__261 
3
2 3
102 0
32 0
1
0 103 5 6
1
end_operator
begin_operator
move_forward__262 
3
2 3
102 6
62 0
1
0 103 5 6
1
end_operator
begin_operator
move_forward__263 
3
2 3
102 7
63 0
1
0 103 5 6
1
end_operator
begin_operator
move_forward__264 
3
2 3
102 8
64 0
1
0 103 5 6
1
end_operator
begin_operator
move_forward__265 
3
2 3
102 10
65 0
1
0 103 5 6
1
end_operator
begin_operator
move_forward__266 
3
2 3
102 12
66 0
1
0 103 5 6
1
end_operator
begin_operator
move_forward__267 
3
2 3
102 2
60 0
1
0 103 5 6
1
end_operator
begin_operator
move_forward__268 
3
2 3
102 3
61 0
1
0 103 5 6
1
end_operator
begin_operator
move_forward__269 
3
2 3
102 4
33 0
1
0 103 5 6
1
end_operator
begin_operator
move_forward__27 
3
2 0
103 8
75 0
1
0 102 6 7
1
end_operator
begin_operator
move_forward__270 
3
2 3
102 0
34 0
1
0 103 6 7
1
end_operator
begin_operator
move_forward__271 
3
2 3
102 8
68 0
1
0 103 6 7
1
end_operator
begin_operator
move_forward__272 
3
2 3
102 10
69 0
1
0 103 6 7
1
end_operator
begin_operator
move_forward__273 
3
2 3
102 12
70 0
1
0 103 6 7
1
end_operator
begin_operator
move_forward__274 
3
2 3
102 2
67 0
1
0 103 6 7
1
end_operator
begin_operator
move_forward__275 
3
2 3
102 0
35 0
1
0 103 7 8
1
end_operator
begin_operator
move_forward__276 
3
2 3
102 5
73 0
1
0 103 7 8
1
end_operator
begin_operator
move_forward__277 
3
2 3
102 6
74 0
1
0 103 7 8
1
end_operator
begin_operator
move_forward__278 
3
2 3
102 7
75 0
1
0 103 7 8
1
end_operator
begin_operator
move_forward__279 
3
2 3
102 8
76 0
1
0 103 7 8
1
end_operator
begin_operator
move_forward__28 
3
2 0
103 8
76 0
1
0 102 7 8
1
end_operator
begin_operator
move_forward__280 
3
2 3
102 10
77 0
1
0 103 7 8
1
end_operator
begin_operator
move_forward__281 
3
2 3
102 11
78 0
1
0 103 7 8
1
end_operator
begin_operator
move_forward__282 
3
2 3
102 12
79 0
1
0 103 7 8
1
end_operator
begin_operator
move_forward__283 
3
2 3
102 2
71 0
1
0 103 7 8
1
end_operator
begin_operator
move_forward__284 
3
2 3
102 3
72 0
1
0 103 7 8
1
end_operator
begin_operator
move_forward__285 
3
2 3
102 4
36 0
1
0 103 7 8
1
end_operator
begin_operator
move_forward__286 
3
2 3
102 10
80 0
1
0 103 8 9
1
end_operator
begin_operator
move_forward__287 
3
2 3
102 4
37 0
1
0 103 8 9
1
end_operator
begin_operator
move_forward__288 
3
2 3
102 0
38 0
1
0 103 9 10
1
end_operator
begin_operator
move_forward__289 
3
2 3
102 5
83 0
1
0 103 9 10
1
end_operator
begin_operator
move_forward__29 
3
2 0
103 8
77 0
1
0 102 9 10
1
end_operator
begin_operator
move_forward__290 
3
2 3
102 6
84 0
1
0 103 9 10
1
end_operator
begin_operator
move_forward__291 
3
2 3
102 7
85 0
1
0 103 9 10
1
end_operator
begin_operator
move_forward__292 
3
2 3
102 8
86 0
1
0 103 9 10
1
end_operator
begin_operator
move_forward__293 
3
2 3
102 10
87 0
1
0 103 9 10
1
end_operator
begin_operator
move_forward__294 
3
2 3
102 11
88 0
1
0 103 9 10
1
end_operator
begin_operator
move_forward__295 
3
2 3
102 12
89 0
1
0 103 9 10
1
end_operator
begin_operator
move_forward__296 
3
2 3
102 2
81 0
1
0 103 9 10
1
end_operator
begin_operator
move_forward__297 
3
2 3
102 3
82 0
1
0 103 9 10
1
end_operator
begin_operator
move_forward__298 
3
2 3
102 4
39 0
1
0 103 9 10
1
end_operator
begin_operator
move_forward__299 
3
2 3
102 0
40 0
1
0 103 10 11
1
end_operator
begin_operator
move_forward__3 
3
2 0
103 0
12 0
1
0 102 8 9
1
end_operator
begin_operator
move_forward__30 
3
2 0
103 8
78 0
1
0 102 10 11
1
end_operator
begin_operator
move_forward__300 
3
2 3
102 8
91 0
1
0 103 10 11
1
end_operator
begin_operator
move_forward__301 
3
2 3
102 12
92 0
1
0 103 10 11
1
end_operator
begin_operator
move_forward__302 
3
2 3
102 2
90 0
1
0 103 10 11
1
end_operator
begin_operator
move_forward__303 
3
2 3
102 4
41 0
1
0 103 10 11
1
end_operator
begin_operator
move_forward__304 
3
2 3
102 0
42 0
1
0 103 11 12
1
end_operator
begin_operator
move_forward__305 
3
2 3
102 5
94 0
1
0 103 11 12
1
end_operator
begin_operator
move_forward__306 
3
2 3
102 6
95 0
1
0 103 11 12
1
end_operator
begin_operator
move_forward__307 
3
2 3
102 8
96 0
1
0 103 11 12
1
end_operator
begin_operator
move_forward__308 
3
2 3
102 9
97 0
1
0 103 11 12
1
end_operator
begin_operator
move_forward__309 
3
2 3
102 10
98 0
1
0 103 11 12
1
end_operator
begin_operator
move_forward__31 
3
2 0
103 8
79 0
1
0 102 11 12
1
end_operator
begin_operator
move_forward__310 
3
2 3
102 12
99 0
1
0 103 11 12
1
end_operator
begin_operator
move_forward__311 
3
2 3
102 2
93 0
1
0 103 11 12
1
end_operator
begin_operator
move_forward__312 
3
2 3
102 4
43 0
1
0 103 11 12
1
end_operator
begin_operator
move_forward__313 
3
2 3
102 6
45 0
1
0 103 12 1
1
end_operator
begin_operator
move_forward__314 
3
2 3
102 8
46 0
1
0 103 12 1
1
end_operator
begin_operator
move_forward__315 
3
2 3
102 12
47 0
1
0 103 12 1
1
end_operator
begin_operator
move_forward__316 
3
2 3
102 2
44 0
1
0 103 12 1
1
end_operator
begin_operator
move_forward__317 
3
2 3
102 4
16 0
1
0 103 12 1
1
end_operator
begin_operator
move_forward__318 
3
2 3
102 0
17 0
1
0 103 1 2
1
end_operator
begin_operator
move_forward__319 
3
2 3
102 5
49 0
1
0 103 1 2
1
end_operator
begin_operator
move_forward__32 
3
2 0
103 8
71 0
1
0 102 1 2
1
end_operator
begin_operator
move_forward__320 
3
2 3
102 6
50 0
1
0 103 1 2
1
end_operator
begin_operator
move_forward__321 
3
2 3
102 8
51 0
1
0 103 1 2
1
end_operator
begin_operator
move_forward__322 
3
2 3
102 10
52 0
1
0 103 1 2
1
end_operator
begin_operator
move_forward__323 
3
2 3
102 11
53 0
1
0 103 1 2
1
end_operator
begin_operator
move_forward__324 
3
2 3
102 12
54 0
1
0 103 1 2
1
end_operator
begin_operator
move_forward__325 
3
2 3
102 2
48 0
1
0 103 1 2
1
end_operator
begin_operator
move_forward__326 
3
2 3
102 4
18 0
1
0 103 1 2
1
end_operator
begin_operator
move_forward__327 
3
2 3
102 0
19 0
1
0 103 2 3
1
end_operator
begin_operator
move_forward__328 
3
2 3
102 8
56 0
1
0 103 2 3
1
end_operator
begin_operator
move_forward__329 
3
2 3
102 10
57 0
1
0 103 2 3
1
end_operator
begin_operator
move_forward__33 
3
2 0
103 8
72 0
1
0 102 2 3
1
end_operator
begin_operator
move_forward__330 
3
2 3
102 2
55 0
1
0 103 2 3
1
end_operator
begin_operator
move_forward__331 
3
2 3
102 4
20 0
1
0 103 2 3
1
end_operator
begin_operator
move_forward__332 
3
2 3
102 0
5 0
1
0 103 3 4
1
end_operator
begin_operator
move_forward__333 
3
2 3
102 5
23 0
1
0 103 3 4
1
end_operator
begin_operator
move_forward__334 
3
2 3
102 6
24 0
1
0 103 3 4
1
end_operator
begin_operator
move_forward__335 
3
2 3
102 8
25 0
1
0 103 3 4
1
end_operator
begin_operator
move_forward__336 
3
2 3
102 9
26 0
1
0 103 3 4
1
end_operator
begin_operator
move_forward__337 
3
2 3
102 10
27 0
1
0 103 3 4
1
end_operator
begin_operator
move_forward__338 
3
2 3
102 11
28 0
1
0 103 3 4
1
end_operator
begin_operator
move_forward__339 
3
2 3
102 12
29 0
1
0 103 3 4
1
end_operator
begin_operator
move_forward__34 
3
2 0
103 8
36 0
1
0 102 3 4
1
end_operator
begin_operator
move_forward__340 
3
2 3
102 1
21 0
1
0 103 3 4
1
end_operator
begin_operator
move_forward__341 
3
2 3
102 2
22 0
1
0 103 3 4
1
end_operator
begin_operator
move_forward__342 
3
2 3
102 4
6 0
1
0 103 3 4
1
end_operator
begin_operator
move_forward__35 
3
2 0
103 9
80 0
1
0 102 9 10
1
end_operator
begin_operator
move_forward__36 
3
2 0
103 9
37 0
1
0 102 3 4
1
end_operator
begin_operator
move_forward__37 
3
2 0
103 10
83 0
1
0 102 0 5
1
end_operator
begin_operator
move_forward__38 
3
2 0
103 10
84 0
1
0 102 5 6
1
end_operator
begin_operator
move_forward__39 
3
2 0
103 10
85 0
1
0 102 6 7
1
end_operator
begin_operator
move_forward__4 
3
2 0
103 0
13 0
1
0 102 9 10
1
end_operator
begin_operator
move_forward__40 
3
2 0
103 10
86 0
1
0 102 7 8
1
end_operator
begin_operator
move_forward__41 
3
2 0
103 10
87 0
1
0 102 9 10
1
end_operator
begin_operator
move_forward__42 
3
2 0
103 10
88 0
1
0 102 10 11
1
end_operator
begin_operator
move_forward__43 
3
2 0
103 10
89 0
1
0 102 11 12
1
end_operator
begin_operator
move_forward__44 
3
2 0
103 10
81 0
1
0 102 1 2
1
end_operator
begin_operator
move_forward__45 
3
2 0
103 10
82 0
1
0 102 2 3
1
end_operator
begin_operator
move_forward__46 
3
2 0
103 10
39 0
1
0 102 3 4
1
end_operator
begin_operator
move_forward__47 
3
2 0
103 11
91 0
1
0 102 7 8
1
end_operator
begin_operator
move_forward__48 
3
2 0
103 11
92 0
1
0 102 11 12
1
end_operator
begin_operator
move_forward__49 
3
2 0
103 11
90 0
1
0 102 1 2
1
end_operator
begin_operator
move_forward__5 
3
2 0
103 0
14 0
1
0 102 10 11
1
end_operator
begin_operator
move_forward__50 
3
2 0
103 11
41 0
1
0 102 3 4
1
end_operator
begin_operator
move_forward__51 
3
2 0
103 12
94 0
1
0 102 0 5
1
end_operator
begin_operator
move_forward__52 
3
2 0
103 12
95 0
1
0 102 5 6
1
end_operator
begin_operator
move_forward__53 
3
2 0
103 12
96 0
1
0 102 7 8
1
end_operator
begin_operator
move_forward__54 
3
2 0
103 12
97 0
1
0 102 8 9
1
end_operator
begin_operator
move_forward__55 
3
2 0
103 12
98 0
1
0 102 9 10
1
end_operator
begin_operator
move_forward__56 
3
2 0
103 12
99 0
1
0 102 11 12
1
end_operator
begin_operator
move_forward__57 
3
2 0
103 12
93 0
1
0 102 1 2
1
end_operator
begin_operator
move_forward__58 
3
2 0
103 12
43 0
1
0 102 3 4
1
end_operator
begin_operator
move_forward__59 
3
2 0
103 1
45 0
1
0 102 5 6
1
end_operator
begin_operator
move_forward__6 
3
2 0
103 0
15 0
1
0 102 11 12
1
end_operator
begin_operator
move_forward__60 
3
2 0
103 1
46 0
1
0 102 7 8
1
end_operator
begin_operator
move_forward__61 
3
2 0
103 1
47 0
1
0 102 11 12
1
end_operator
begin_operator
move_forward__62 
3
2 0
103 1
44 0
1
0 102 1 2
1
end_operator
begin_operator
move_forward__63 
3
2 0
103 1
16 0
1
0 102 3 4
1
end_operator
begin_operator
move_forward__64 
3
2 0
103 2
49 0
1
0 102 0 5
1
end_operator
begin_operator
move_forward__65 
3
2 0
103 2
50 0
1
0 102 5 6
1
end_operator
begin_operator
move_forward__66 
3
2 0
103 2
51 0
1
0 102 7 8
1
end_operator
begin_operator
move_forward__67 
3
2 0
103 2
52 0
1
0 102 9 10
1
end_operator
begin_operator
move_forward__68 
3
2 0
103 2
53 0
1
0 102 10 11
1
end_operator
begin_operator
move_forward__69 
3
2 0
103 2
54 0
1
0 102 11 12
1
end_operator
begin_operator
move_forward__7 
3
2 0
103 0
7 0
1
0 102 1 2
1
end_operator
begin_operator
move_forward__70 
3
2 0
103 2
48 0
1
0 102 1 2
1
end_operator
begin_operator
move_forward__71 
3
2 0
103 2
18 0
1
0 102 3 4
1
end_operator
begin_operator
move_forward__72 
3
2 0
103 3
56 0
1
0 102 7 8
1
end_operator
begin_operator
move_forward__73 
3
2 0
103 3
57 0
1
0 102 9 10
1
end_operator
begin_operator
move_forward__74 
3
2 0
103 3
55 0
1
0 102 1 2
1
end_operator
begin_operator
move_forward__75 
3
2 0
103 3
20 0
1
0 102 3 4
1
end_operator
begin_operator
move_forward__76 
3
2 0
103 4
23 0
1
0 102 0 5
1
end_operator
begin_operator
move_forward__77 
3
2 0
103 4
24 0
1
0 102 5 6
1
end_operator
begin_operator
move_forward__78 
3
2 0
103 4
25 0
1
0 102 7 8
1
end_operator
begin_operator
move_forward__79 
3
2 0
103 4
26 0
1
0 102 8 9
1
end_operator
begin_operator
move_forward__8 
3
2 0
103 0
8 0
1
0 102 2 3
1
end_operator
begin_operator
move_forward__80 
3
2 0
103 4
27 0
1
0 102 9 10
1
end_operator
begin_operator
move_forward__81 
3
2 0
103 4
28 0
1
0 102 10 11
1
end_operator
begin_operator
move_forward__82 
3
2 0
103 4
29 0
1
0 102 11 12
1
end_operator
begin_operator
move_forward__83 
3
2 0
103 4
21 0
1
0 102 12 1
1
end_operator
begin_operator
move_forward__84 
3
2 0
103 4
22 0
1
0 102 1 2
1
end_operator
begin_operator
move_forward__85 
3
2 0
103 4
6 0
1
0 102 3 4
1
end_operator
begin_operator
move_forward__86 
3
2 2
103 0
3 0
1
0 102 5 0
1
end_operator
begin_operator
move_forward__87 
3
2 2
103 0
9 0
1
0 102 7 6
1
end_operator
begin_operator
move_forward__88 
3
2 2
103 0
10 0
1
0 102 8 7
1
end_operator
begin_operator
move_forward__89 
3
2 2
103 0
11 0
1
0 102 9 8
1
end_operator
begin_operator
move_forward__9 
3
2 0
103 0
4 0
1
0 102 3 4
1
end_operator
begin_operator
move_forward__90 
3
2 2
103 0
12 0
1
0 102 10 9
1
end_operator
begin_operator
move_forward__91 
3
2 2
103 0
13 0
1
0 102 11 10
1
end_operator
begin_operator
move_forward__92 
3
2 2
103 0
14 0
1
0 102 12 11
1
end_operator
begin_operator
move_forward__93 
3
2 2
103 0
15 0
1
0 102 1 12
1
end_operator
begin_operator
move_forward__94 
3
2 2
103 0
7 0
1
0 102 3 2
1
end_operator
begin_operator
move_forward__95 
3
2 2
103 0
8 0
1
0 102 4 3
1
end_operator
begin_operator
move_forward__96 
3
2 2
103 5
30 0
1
0 102 5 0
1
end_operator
begin_operator
move_forward__97 
3
2 2
103 5
58 0
1
0 102 7 6
1
end_operator
begin_operator
move_forward__98 
3
2 2
103 5
59 0
1
0 102 1 12
1
end_operator
begin_operator
move_forward__99 
3
2 2
103 6
32 0
1
0 102 5 0
1
end_operator
begin_operator
place_block__0 
5
2 0
1 1
0 1
103 0
102 5
3
0 9 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__1 
6
2 0
1 1
0 1
103 0
102 5
100 1
2
0 9 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__10 
5
2 0
1 1
0 1
103 0
102 10
3
0 14 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__100 
5
2 0
1 1
0 1
103 11
102 3
3
0 41 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__101 
6
2 0
1 1
0 1
103 11
102 3
100 1
2
0 41 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__102 
5
2 0
1 1
0 1
103 12
102 0
3
0 94 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__103 
6
2 0
1 1
0 1
103 12
102 0
100 1
2
0 94 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__104 
5
2 0
1 1
0 1
103 12
102 5
3
0 95 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__105 
6
2 0
1 1
0 1
103 12
102 5
100 1
2
0 95 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__106 
5
2 0
1 1
0 1
103 12
102 7
3
0 96 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__107 
6
2 0
1 1
0 1
103 12
102 7
100 1
2
0 96 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__108 
5
2 0
1 1
0 1
103 12
102 8
3
0 97 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__109 
6
2 0
1 1
0 1
103 12
102 8
100 1
2
0 97 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__11 
6
2 0
1 1
0 1
103 0
102 10
100 1
2
0 14 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__110 
5
2 0
1 1
0 1
103 12
102 9
3
0 98 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__111 
6
2 0
1 1
0 1
103 12
102 9
100 1
2
0 98 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__112 
5
2 0
1 1
0 1
103 12
102 11
3
0 99 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__113 
6
2 0
1 1
0 1
103 12
102 11
100 1
2
0 99 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__114 
5
2 0
1 1
0 1
103 12
102 1
3
0 93 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__115 
6
2 0
1 1
0 1
103 12
102 1
100 1
2
0 93 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__116 
5
2 0
1 1
0 1
103 12
102 3
3
0 43 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__117 
6
2 0
1 1
0 1
103 12
102 3
100 1
2
0 43 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__118 
5
2 0
1 1
0 1
103 1
102 5
3
0 45 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__119 
6
2 0
1 1
0 1
103 1
102 5
100 1
2
0 45 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__12 
5
2 0
1 1
0 1
103 0
102 11
3
0 15 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__120 
5
2 0
1 1
0 1
103 1
102 7
3
0 46 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__121 
6
2 0
1 1
0 1
103 1
102 7
100 1
2
0 46 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__122 
5
2 0
1 1
0 1
103 1
102 11
3
0 47 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__123 
6
2 0
1 1
0 1
103 1
102 11
100 1
2
0 47 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__124 
5
2 0
1 1
0 1
103 1
102 1
3
0 44 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__125 
6
2 0
1 1
0 1
103 1
102 1
100 1
2
0 44 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__126 
5
2 0
1 1
0 1
103 1
102 3
3
0 16 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__127 
6
2 0
1 1
0 1
103 1
102 3
100 1
2
0 16 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__128 
5
2 0
1 1
0 1
103 2
102 0
3
0 49 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__129 
6
2 0
1 1
0 1
103 2
102 0
100 1
2
0 49 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__13 
6
2 0
1 1
0 1
103 0
102 11
100 1
2
0 15 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__130 
5
2 0
1 1
0 1
103 2
102 5
3
0 50 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__131 
6
2 0
1 1
0 1
103 2
102 5
100 1
2
0 50 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__132 
5
2 0
1 1
0 1
103 2
102 7
3
0 51 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__133 
6
2 0
1 1
0 1
103 2
102 7
100 1
2
0 51 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__134 
5
2 0
1 1
0 1
103 2
102 9
3
0 52 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__135 
6
2 0
1 1
0 1
103 2
102 9
100 1
2
0 52 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__136 
5
2 0
1 1
0 1
103 2
102 10
3
0 53 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__137 
6
2 0
1 1
0 1
103 2
102 10
100 1
2
0 53 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__138 
5
2 0
1 1
0 1
103 2
102 11
3
0 54 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__139 
6
2 0
1 1
0 1
103 2
102 11
100 1
2
0 54 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__14 
5
2 0
1 1
0 1
103 0
102 1
3
0 7 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__140 
5
2 0
1 1
0 1
103 2
102 1
3
0 48 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__141 
6
2 0
1 1
0 1
103 2
102 1
100 1
2
0 48 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__142 
5
2 0
1 1
0 1
103 2
102 3
3
0 18 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__143 
6
2 0
1 1
0 1
103 2
102 3
100 1
2
0 18 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__144 
5
2 0
1 1
0 1
103 3
102 7
3
0 56 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__145 
6
2 0
1 1
0 1
103 3
102 7
100 1
2
0 56 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__146 
5
2 0
1 1
0 1
103 3
102 9
3
0 57 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__147 
6
2 0
1 1
0 1
103 3
102 9
100 1
2
0 57 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__148 
5
2 0
1 1
0 1
103 3
102 1
3
0 55 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__149 
6
2 0
1 1
0 1
103 3
102 1
100 1
2
0 55 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__15 
6
2 0
1 1
0 1
103 0
102 1
100 1
2
0 7 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__150 
5
2 0
1 1
0 1
103 3
102 3
3
0 20 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__151 
6
2 0
1 1
0 1
103 3
102 3
100 1
2
0 20 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__152 
5
2 0
1 1
0 1
103 4
102 0
3
0 23 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__153 
6
2 0
1 1
0 1
103 4
102 0
100 1
2
0 23 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__154 
5
2 0
1 1
0 1
103 4
102 5
3
0 24 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__155 
6
2 0
1 1
0 1
103 4
102 5
100 1
2
0 24 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__156 
5
2 0
1 1
0 1
103 4
102 7
3
0 25 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__157 
6
2 0
1 1
0 1
103 4
102 7
100 1
2
0 25 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__158 
5
2 0
1 1
0 1
103 4
102 8
3
0 26 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__159 
6
2 0
1 1
0 1
103 4
102 8
100 1
2
0 26 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__16 
5
2 0
1 1
0 1
103 0
102 2
3
0 8 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__160 
5
2 0
1 1
0 1
103 4
102 9
3
0 27 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__161 
6
2 0
1 1
0 1
103 4
102 9
100 1
2
0 27 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__162 
5
2 0
1 1
0 1
103 4
102 10
3
0 28 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__163 
6
2 0
1 1
0 1
103 4
102 10
100 1
2
0 28 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__164 
5
2 0
1 1
0 1
103 4
102 11
3
0 29 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__165 
6
2 0
1 1
0 1
103 4
102 11
100 1
2
0 29 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__166 
5
2 0
1 1
0 1
103 4
102 12
3
0 21 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__167 
6
2 0
1 1
0 1
103 4
102 12
100 1
2
0 21 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__168 
5
2 0
1 1
0 1
103 4
102 1
3
0 22 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__169 
6
2 0
1 1
0 1
103 4
102 1
100 1
2
0 22 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__17 
6
2 0
1 1
0 1
103 0
102 2
100 1
2
0 8 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__170 
5
2 0
1 1
0 1
103 4
102 3
3
0 6 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__171 
6
2 0
1 1
0 1
103 4
102 3
100 1
2
0 6 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__172 
5
2 2
1 1
0 1
103 0
102 5
3
0 3 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__173 
6
2 2
1 1
0 1
103 0
102 5
100 1
2
0 3 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__174 
5
2 2
1 1
0 1
103 0
102 7
3
0 9 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__175 
6
2 2
1 1
0 1
103 0
102 7
100 1
2
0 9 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__176 
5
2 2
1 1
0 1
103 0
102 8
3
0 10 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__177 
6
2 2
1 1
0 1
103 0
102 8
100 1
2
0 10 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__178 
5
2 2
1 1
0 1
103 0
102 9
3
0 11 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__179 
6
2 2
1 1
0 1
103 0
102 9
100 1
2
0 11 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__18 
5
2 0
1 1
0 1
103 0
102 3
3
0 4 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__180 
5
2 2
1 1
0 1
103 0
102 10
3
0 12 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__181 
6
2 2
1 1
0 1
103 0
102 10
100 1
2
0 12 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__182 
5
2 2
1 1
0 1
103 0
102 11
3
0 13 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__183 
6
2 2
1 1
0 1
103 0
102 11
100 1
2
0 13 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__184 
5
2 2
1 1
0 1
103 0
102 12
3
0 14 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__185 
6
2 2
1 1
0 1
103 0
102 12
100 1
2
0 14 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__186 
5
2 2
1 1
0 1
103 0
102 1
3
0 15 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__187 
6
2 2
1 1
0 1
103 0
102 1
100 1
2
0 15 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__188 
5
2 2
1 1
0 1
103 0
102 3
3
0 7 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__189 
6
2 2
1 1
0 1
103 0
102 3
100 1
2
0 7 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__19 
6
2 0
1 1
0 1
103 0
102 3
100 1
2
0 4 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__190 
5
2 2
1 1
0 1
103 0
102 4
3
0 8 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__191 
6
2 2
1 1
0 1
103 0
102 4
100 1
2
0 8 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__192 
5
2 2
1 1
0 1
103 5
102 5
3
0 30 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__193 
6
2 2
1 1
0 1
103 5
102 5
100 1
2
0 30 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__194 
5
2 2
1 1
0 1
103 5
102 7
3
0 58 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__195 
6
2 2
1 1
0 1
103 5
102 7
100 1
2
0 58 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__196 
5
2 2
1 1
0 1
103 5
102 1
3
0 59 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__197 
6
2 2
1 1
0 1
103 5
102 1
100 1
2
0 59 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__198 
5
2 2
1 1
0 1
103 6
102 5
3
0 32 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__199 
6
2 2
1 1
0 1
103 6
102 5
100 1
2
0 32 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__2 
5
2 0
1 1
0 1
103 0
102 6
3
0 10 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__20 
5
2 0
1 1
0 1
103 5
102 5
3
0 58 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__200 
5
2 2
1 1
0 1
103 6
102 7
3
0 62 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__201 
6
2 2
1 1
0 1
103 6
102 7
100 1
2
0 62 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__202 
5
2 2
1 1
0 1
103 6
102 8
3
0 63 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__203 
6
2 2
1 1
0 1
103 6
102 8
100 1
2
0 63 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__204 
5
2 2
1 1
0 1
103 6
102 9
3
0 64 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__205 
6
2 2
1 1
0 1
103 6
102 9
100 1
2
0 64 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__206 
5
2 2
1 1
0 1
103 6
102 11
3
0 65 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__207 
6
2 2
1 1
0 1
103 6
102 11
100 1
2
0 65 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__208 
5
2 2
1 1
0 1
103 6
102 1
3
0 66 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__209 
6
2 2
1 1
0 1
103 6
102 1
100 1
2
0 66 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__21 
6
2 0
1 1
0 1
103 5
102 5
100 1
2
0 58 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__210 
5
2 2
1 1
0 1
103 6
102 3
3
0 60 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__211 
6
2 2
1 1
0 1
103 6
102 3
100 1
2
0 60 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__212 
5
2 2
1 1
0 1
103 6
102 4
3
0 61 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__213 
6
2 2
1 1
0 1
103 6
102 4
100 1
2
0 61 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__214 
5
2 2
1 1
0 1
103 7
102 5
3
0 34 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__215 
6
2 2
1 1
0 1
103 7
102 5
100 1
2
0 34 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__216 
5
2 2
1 1
0 1
103 7
102 9
3
0 68 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__217 
6
2 2
1 1
0 1
103 7
102 9
100 1
2
0 68 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__218 
5
2 2
1 1
0 1
103 7
102 11
3
0 69 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__219 
6
2 2
1 1
0 1
103 7
102 11
100 1
2
0 69 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__22 
5
2 0
1 1
0 1
103 5
102 11
3
0 59 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__220 
5
2 2
1 1
0 1
103 7
102 1
3
0 70 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__221 
6
2 2
1 1
0 1
103 7
102 1
100 1
2
0 70 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__222 
5
2 2
1 1
0 1
103 7
102 3
3
0 67 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__223 
6
2 2
1 1
0 1
103 7
102 3
100 1
2
0 67 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__224 
5
2 2
1 1
0 1
103 8
102 5
3
0 35 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__225 
6
2 2
1 1
0 1
103 8
102 5
100 1
2
0 35 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__226 
5
2 2
1 1
0 1
103 8
102 6
3
0 73 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__227 
6
2 2
1 1
0 1
103 8
102 6
100 1
2
0 73 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__228 
5
2 2
1 1
0 1
103 8
102 7
3
0 74 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__229 
6
2 2
1 1
0 1
103 8
102 7
100 1
2
0 74 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__23 
6
2 0
1 1
0 1
103 5
102 11
100 1
2
0 59 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__230 
5
2 2
1 1
0 1
103 8
102 8
3
0 75 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__231 
6
2 2
1 1
0 1
103 8
102 8
100 1
2
0 75 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__232 
5
2 2
1 1
0 1
103 8
102 9
3
0 76 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__233 
6
2 2
1 1
0 1
103 8
102 9
100 1
2
0 76 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__234 
5
2 2
1 1
0 1
103 8
102 11
3
0 77 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__235 
6
2 2
1 1
0 1
103 8
102 11
100 1
2
0 77 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__236 
5
2 2
1 1
0 1
103 8
102 12
3
0 78 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__237 
6
2 2
1 1
0 1
103 8
102 12
100 1
2
0 78 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__238 
5
2 2
1 1
0 1
103 8
102 1
3
0 79 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__239 
6
2 2
1 1
0 1
103 8
102 1
100 1
2
0 79 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__24 
5
2 0
1 1
0 1
103 5
102 3
3
0 31 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__240 
5
2 2
1 1
0 1
103 8
102 3
3
0 71 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__241 
6
2 2
1 1
0 1
103 8
102 3
100 1
2
0 71 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__242 
5
2 2
1 1
0 1
103 8
102 4
3
0 72 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__243 
6
2 2
1 1
0 1
103 8
102 4
100 1
2
0 72 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__244 
5
2 2
1 1
0 1
103 9
102 11
3
0 80 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__245 
6
2 2
1 1
0 1
103 9
102 11
100 1
2
0 80 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__246 
5
2 2
1 1
0 1
103 10
102 5
3
0 38 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__247 
6
2 2
1 1
0 1
103 10
102 5
100 1
2
0 38 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__248 
5
2 2
1 1
0 1
103 10
102 6
3
0 83 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__249 
6
2 2
1 1
0 1
103 10
102 6
100 1
2
0 83 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__25 
6
2 0
1 1
0 1
103 5
102 3
100 1
2
0 31 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__250 
5
2 2
1 1
0 1
103 10
102 7
3
0 84 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__251 
6
2 2
1 1
0 1
103 10
102 7
100 1
2
0 84 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__252 
5
2 2
1 1
0 1
103 10
102 8
3
0 85 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__253 
6
2 2
1 1
0 1
103 10
102 8
100 1
2
0 85 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__254 
5
2 2
1 1
0 1
103 10
102 9
3
0 86 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__255 
6
2 2
1 1
0 1
103 10
102 9
100 1
2
0 86 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__256 
5
2 2
1 1
0 1
103 10
102 11
3
0 87 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__257 
6
2 2
1 1
0 1
103 10
102 11
100 1
2
0 87 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__258 
5
2 2
1 1
0 1
103 10
102 12
3
0 88 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__259 
6
2 2
1 1
0 1
103 10
102 12
100 1
2
0 88 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__26 
5
2 0
1 1
0 1
103 6
102 5
3
0 62 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__260 
5
2 2
1 1
0 1
103 10
102 1
3
0 89 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__261 
6
2 2
1 1
0 1
103 10
102 1
100 1
2
0 89 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__262 
5
2 2
1 1
0 1
103 10
102 3
3
0 81 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__263 
6
2 2
1 1
0 1
103 10
102 3
100 1
2
0 81 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__264 
5
2 2
1 1
0 1
103 10
102 4
3
0 82 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__265 
6
2 2
1 1
0 1
103 10
102 4
100 1
2
0 82 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__266 
5
2 2
1 1
0 1
103 11
102 5
3
0 40 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__267 
6
2 2
1 1
0 1
103 11
102 5
100 1
2
0 40 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__268 
5
2 2
1 1
0 1
103 11
102 9
3
0 91 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__269 
6
2 2
1 1
0 1
103 11
102 9
100 1
2
0 91 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__27 
6
2 0
1 1
0 1
103 6
102 5
100 1
2
0 62 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__270 
5
2 2
1 1
0 1
103 11
102 1
3
0 92 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__271 
6
2 2
1 1
0 1
103 11
102 1
100 1
2
0 92 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__272 
5
2 2
1 1
0 1
103 11
102 3
3
0 90 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__273 
6
2 2
1 1
0 1
103 11
102 3
100 1
2
0 90 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__274 
5
2 2
1 1
0 1
103 12
102 5
3
0 42 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__275 
6
2 2
1 1
0 1
103 12
102 5
100 1
2
0 42 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__276 
5
2 2
1 1
0 1
103 12
102 6
3
0 94 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__277 
6
2 2
1 1
0 1
103 12
102 6
100 1
2
0 94 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__278 
5
2 2
1 1
0 1
103 12
102 7
3
0 95 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__279 
6
2 2
1 1
0 1
103 12
102 7
100 1
2
0 95 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__28 
5
2 0
1 1
0 1
103 6
102 6
3
0 63 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__280 
5
2 2
1 1
0 1
103 12
102 9
3
0 96 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__281 
6
2 2
1 1
0 1
103 12
102 9
100 1
2
0 96 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__282 
5
2 2
1 1
0 1
103 12
102 10
3
0 97 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__283 
6
2 2
1 1
0 1
103 12
102 10
100 1
2
0 97 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__284 
5
2 2
1 1
0 1
103 12
102 11
3
0 98 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__285 
6
2 2
1 1
0 1
103 12
102 11
100 1
2
0 98 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__286 
5
2 2
1 1
0 1
103 12
102 1
3
0 99 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__287 
6
2 2
1 1
0 1
103 12
102 1
100 1
2
0 99 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__288 
5
2 2
1 1
0 1
103 12
102 3
3
0 93 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__289 
6
2 2
1 1
0 1
103 12
102 3
100 1
2
0 93 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__29 
6
2 0
1 1
0 1
103 6
102 6
100 1
2
0 63 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__290 
5
2 2
1 1
0 1
103 1
102 7
3
0 45 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__291 
6
2 2
1 1
0 1
103 1
102 7
100 1
2
0 45 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__292 
5
2 2
1 1
0 1
103 1
102 9
3
0 46 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__293 
6
2 2
1 1
0 1
103 1
102 9
100 1
2
0 46 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__294 
5
2 2
1 1
0 1
103 1
102 1
3
0 47 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__295 
6
2 2
1 1
0 1
103 1
102 1
100 1
2
0 47 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__296 
5
2 2
1 1
0 1
103 1
102 3
3
0 44 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__297 
6
2 2
1 1
0 1
103 1
102 3
100 1
2
0 44 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__298 
5
2 2
1 1
0 1
103 2
102 5
3
0 17 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__299 
6
2 2
1 1
0 1
103 2
102 5
100 1
2
0 17 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__3 
6
2 0
1 1
0 1
103 0
102 6
100 1
2
0 10 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__30 
5
2 0
1 1
0 1
103 6
102 7
3
0 64 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__300 
5
2 2
1 1
0 1
103 2
102 6
3
0 49 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__301 
6
2 2
1 1
0 1
103 2
102 6
100 1
2
0 49 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__302 
5
2 2
1 1
0 1
103 2
102 7
3
0 50 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__303 
6
2 2
1 1
0 1
103 2
102 7
100 1
2
0 50 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__304 
5
2 2
1 1
0 1
103 2
102 9
3
0 51 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__305 
6
2 2
1 1
0 1
103 2
102 9
100 1
2
0 51 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__306 
5
2 2
1 1
0 1
103 2
102 11
3
0 52 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__307 
6
2 2
1 1
0 1
103 2
102 11
100 1
2
0 52 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__308 
5
2 2
1 1
0 1
103 2
102 12
3
0 53 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__309 
6
2 2
1 1
0 1
103 2
102 12
100 1
2
0 53 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__31 
6
2 0
1 1
0 1
103 6
102 7
100 1
2
0 64 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__310 
5
2 2
1 1
0 1
103 2
102 1
3
0 54 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__311 
6
2 2
1 1
0 1
103 2
102 1
100 1
2
0 54 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__312 
5
2 2
1 1
0 1
103 2
102 3
3
0 48 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__313 
6
2 2
1 1
0 1
103 2
102 3
100 1
2
0 48 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__314 
5
2 2
1 1
0 1
103 3
102 5
3
0 19 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__315 
6
2 2
1 1
0 1
103 3
102 5
100 1
2
0 19 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__316 
5
2 2
1 1
0 1
103 3
102 9
3
0 56 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__317 
6
2 2
1 1
0 1
103 3
102 9
100 1
2
0 56 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__318 
5
2 2
1 1
0 1
103 3
102 11
3
0 57 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__319 
6
2 2
1 1
0 1
103 3
102 11
100 1
2
0 57 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__32 
5
2 0
1 1
0 1
103 6
102 9
3
0 65 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__320 
5
2 2
1 1
0 1
103 3
102 3
3
0 55 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__321 
6
2 2
1 1
0 1
103 3
102 3
100 1
2
0 55 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__322 
5
2 2
1 1
0 1
103 4
102 5
3
0 5 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__323 
6
2 2
1 1
0 1
103 4
102 5
100 1
2
0 5 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__324 
5
2 2
1 1
0 1
103 4
102 6
3
0 23 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__325 
6
2 2
1 1
0 1
103 4
102 6
100 1
2
0 23 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__326 
5
2 2
1 1
0 1
103 4
102 7
3
0 24 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__327 
6
2 2
1 1
0 1
103 4
102 7
100 1
2
0 24 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__328 
5
2 2
1 1
0 1
103 4
102 9
3
0 25 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__329 
6
2 2
1 1
0 1
103 4
102 9
100 1
2
0 25 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__33 
6
2 0
1 1
0 1
103 6
102 9
100 1
2
0 65 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__330 
5
2 2
1 1
0 1
103 4
102 10
3
0 26 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__331 
6
2 2
1 1
0 1
103 4
102 10
100 1
2
0 26 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__332 
5
2 2
1 1
0 1
103 4
102 11
3
0 27 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__333 
6
2 2
1 1
0 1
103 4
102 11
100 1
2
0 27 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__334 
5
2 2
1 1
0 1
103 4
102 12
3
0 28 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__335 
6
2 2
1 1
0 1
103 4
102 12
100 1
2
0 28 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__336 
5
2 2
1 1
0 1
103 4
102 1
3
0 29 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__337 
6
2 2
1 1
0 1
103 4
102 1
100 1
2
0 29 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__338 
5
2 2
1 1
0 1
103 4
102 2
3
0 21 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__339 
6
2 2
1 1
0 1
103 4
102 2
100 1
2
0 21 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__34 
5
2 0
1 1
0 1
103 6
102 11
3
0 66 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__340 
5
2 2
1 1
0 1
103 4
102 3
3
0 22 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__341 
6
2 2
1 1
0 1
103 4
102 3
100 1
2
0 22 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__342 
5
2 1
1 1
0 1
103 5
102 0
3
0 3 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__343 
6
2 1
1 1
0 1
103 5
102 0
100 1
2
0 3 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__344 
5
2 1
1 1
0 1
103 5
102 6
3
0 9 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__345 
6
2 1
1 1
0 1
103 5
102 6
100 1
2
0 9 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__346 
5
2 1
1 1
0 1
103 5
102 7
3
0 10 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__347 
6
2 1
1 1
0 1
103 5
102 7
100 1
2
0 10 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__348 
5
2 1
1 1
0 1
103 5
102 8
3
0 11 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__349 
6
2 1
1 1
0 1
103 5
102 8
100 1
2
0 11 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__35 
6
2 0
1 1
0 1
103 6
102 11
100 1
2
0 66 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__350 
5
2 1
1 1
0 1
103 5
102 9
3
0 12 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__351 
6
2 1
1 1
0 1
103 5
102 9
100 1
2
0 12 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__352 
5
2 1
1 1
0 1
103 5
102 10
3
0 13 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__353 
6
2 1
1 1
0 1
103 5
102 10
100 1
2
0 13 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__354 
5
2 1
1 1
0 1
103 5
102 11
3
0 14 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__355 
6
2 1
1 1
0 1
103 5
102 11
100 1
2
0 14 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__356 
5
2 1
1 1
0 1
103 5
102 12
3
0 15 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__357 
6
2 1
1 1
0 1
103 5
102 12
100 1
2
0 15 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__358 
5
2 1
1 1
0 1
103 5
102 2
3
0 7 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__359 
6
2 1
1 1
0 1
103 5
102 2
100 1
2
0 7 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__36 
5
2 0
1 1
0 1
103 6
102 1
3
0 60 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__360 
5
2 1
1 1
0 1
103 5
102 3
3
0 8 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__361 
6
2 1
1 1
0 1
103 5
102 3
100 1
2
0 8 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__362 
5
2 1
1 1
0 1
103 5
102 4
3
0 4 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__363 
6
2 1
1 1
0 1
103 5
102 4
100 1
2
0 4 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__364 
5
2 1
1 1
0 1
103 6
102 0
3
0 30 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__365 
6
2 1
1 1
0 1
103 6
102 0
100 1
2
0 30 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__366 
5
2 1
1 1
0 1
103 6
102 6
3
0 58 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__367 
6
2 1
1 1
0 1
103 6
102 6
100 1
2
0 58 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__368 
5
2 1
1 1
0 1
103 6
102 12
3
0 59 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__369 
6
2 1
1 1
0 1
103 6
102 12
100 1
2
0 59 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__37 
6
2 0
1 1
0 1
103 6
102 1
100 1
2
0 60 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__370 
5
2 1
1 1
0 1
103 6
102 4
3
0 31 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__371 
6
2 1
1 1
0 1
103 6
102 4
100 1
2
0 31 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__372 
5
2 1
1 1
0 1
103 7
102 0
3
0 32 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__373 
6
2 1
1 1
0 1
103 7
102 0
100 1
2
0 32 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__374 
5
2 1
1 1
0 1
103 7
102 6
3
0 62 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__375 
6
2 1
1 1
0 1
103 7
102 6
100 1
2
0 62 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__376 
5
2 1
1 1
0 1
103 7
102 7
3
0 63 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__377 
6
2 1
1 1
0 1
103 7
102 7
100 1
2
0 63 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__378 
5
2 1
1 1
0 1
103 7
102 8
3
0 64 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__379 
6
2 1
1 1
0 1
103 7
102 8
100 1
2
0 64 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__38 
5
2 0
1 1
0 1
103 6
102 2
3
0 61 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__380 
5
2 1
1 1
0 1
103 7
102 10
3
0 65 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__381 
6
2 1
1 1
0 1
103 7
102 10
100 1
2
0 65 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__382 
5
2 1
1 1
0 1
103 7
102 12
3
0 66 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__383 
6
2 1
1 1
0 1
103 7
102 12
100 1
2
0 66 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__384 
5
2 1
1 1
0 1
103 7
102 2
3
0 60 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__385 
6
2 1
1 1
0 1
103 7
102 2
100 1
2
0 60 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__386 
5
2 1
1 1
0 1
103 7
102 3
3
0 61 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__387 
6
2 1
1 1
0 1
103 7
102 3
100 1
2
0 61 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__388 
5
2 1
1 1
0 1
103 7
102 4
3
0 33 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__389 
6
2 1
1 1
0 1
103 7
102 4
100 1
2
0 33 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__39 
6
2 0
1 1
0 1
103 6
102 2
100 1
2
0 61 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__390 
5
2 1
1 1
0 1
103 8
102 0
3
0 34 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__391 
6
2 1
1 1
0 1
103 8
102 0
100 1
2
0 34 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__392 
5
2 1
1 1
0 1
103 8
102 8
3
0 68 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__393 
6
2 1
1 1
0 1
103 8
102 8
100 1
2
0 68 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__394 
5
2 1
1 1
0 1
103 8
102 10
3
0 69 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__395 
6
2 1
1 1
0 1
103 8
102 10
100 1
2
0 69 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__396 
5
2 1
1 1
0 1
103 8
102 12
3
0 70 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__397 
6
2 1
1 1
0 1
103 8
102 12
100 1
2
0 70 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__398 
5
2 1
1 1
0 1
103 8
102 2
3
0 67 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__399 
6
2 1
1 1
0 1
103 8
102 2
100 1
2
0 67 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__4 
5
2 0
1 1
0 1
103 0
102 7
3
0 11 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__40 
5
2 0
1 1
0 1
103 6
102 3
3
0 33 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__400 
5
2 1
1 1
0 1
103 9
102 0
3
0 35 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__401 
6
2 1
1 1
0 1
103 9
102 0
100 1
2
0 35 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__402 
5
2 1
1 1
0 1
103 9
102 5
3
0 73 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__403 
6
2 1
1 1
0 1
103 9
102 5
100 1
2
0 73 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__404 
5
2 1
1 1
0 1
103 9
102 6
3
0 74 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__405 
6
2 1
1 1
0 1
103 9
102 6
100 1
2
0 74 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__406 
5
2 1
1 1
0 1
103 9
102 7
3
0 75 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__407 
6
2 1
1 1
0 1
103 9
102 7
100 1
2
0 75 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__408 
5
2 1
1 1
0 1
103 9
102 8
3
0 76 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__409 
6
2 1
1 1
0 1
103 9
102 8
100 1
2
0 76 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__41 
6
2 0
1 1
0 1
103 6
102 3
100 1
2
0 33 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__410 
5
2 1
1 1
0 1
103 9
102 10
3
0 77 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__411 
6
2 1
1 1
0 1
103 9
102 10
100 1
2
0 77 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__412 
5
2 1
1 1
0 1
103 9
102 11
3
0 78 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__413 
6
2 1
1 1
0 1
103 9
102 11
100 1
2
0 78 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__414 
5
2 1
1 1
0 1
103 9
102 12
3
0 79 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__415 
6
2 1
1 1
0 1
103 9
102 12
100 1
2
0 79 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__416 
5
2 1
1 1
0 1
103 9
102 2
3
0 71 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__417 
6
2 1
1 1
0 1
103 9
102 2
100 1
2
0 71 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__418 
5
2 1
1 1
0 1
103 9
102 3
3
0 72 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__419 
6
2 1
1 1
0 1
103 9
102 3
100 1
2
0 72 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__42 
5
2 0
1 1
0 1
103 7
102 7
3
0 68 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__420 
5
2 1
1 1
0 1
103 9
102 4
3
0 36 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__421 
6
2 1
1 1
0 1
103 9
102 4
100 1
2
0 36 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__422 
5
2 1
1 1
0 1
103 10
102 10
3
0 80 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__423 
6
2 1
1 1
0 1
103 10
102 10
100 1
2
0 80 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__424 
5
2 1
1 1
0 1
103 10
102 4
3
0 37 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__425 
6
2 1
1 1
0 1
103 10
102 4
100 1
2
0 37 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__426 
5
2 1
1 1
0 1
103 11
102 0
3
0 38 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__427 
6
2 1
1 1
0 1
103 11
102 0
100 1
2
0 38 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__428 
5
2 1
1 1
0 1
103 11
102 5
3
0 83 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__429 
6
2 1
1 1
0 1
103 11
102 5
100 1
2
0 83 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__43 
6
2 0
1 1
0 1
103 7
102 7
100 1
2
0 68 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__430 
5
2 1
1 1
0 1
103 11
102 6
3
0 84 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__431 
6
2 1
1 1
0 1
103 11
102 6
100 1
2
0 84 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__432 
5
2 1
1 1
0 1
103 11
102 7
3
0 85 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__433 
6
2 1
1 1
0 1
103 11
102 7
100 1
2
0 85 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__434 
5
2 1
1 1
0 1
103 11
102 8
3
0 86 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__435 
6
2 1
1 1
0 1
103 11
102 8
100 1
2
0 86 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__436 
5
2 1
1 1
0 1
103 11
102 10
3
0 87 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__437 
6
2 1
1 1
0 1
103 11
102 10
100 1
2
0 87 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__438 
5
2 1
1 1
0 1
103 11
102 11
3
0 88 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__439 
6
2 1
1 1
0 1
103 11
102 11
100 1
2
0 88 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__44 
5
2 0
1 1
0 1
103 7
102 9
3
0 69 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__440 
5
2 1
1 1
0 1
103 11
102 12
3
0 89 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__441 
6
2 1
1 1
0 1
103 11
102 12
100 1
2
0 89 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__442 
5
2 1
1 1
0 1
103 11
102 2
3
0 81 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__443 
6
2 1
1 1
0 1
103 11
102 2
100 1
2
0 81 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__444 
5
2 1
1 1
0 1
103 11
102 3
3
0 82 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__445 
6
2 1
1 1
0 1
103 11
102 3
100 1
2
0 82 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__446 
5
2 1
1 1
0 1
103 11
102 4
3
0 39 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__447 
6
2 1
1 1
0 1
103 11
102 4
100 1
2
0 39 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__448 
5
2 1
1 1
0 1
103 12
102 0
3
0 40 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__449 
6
2 1
1 1
0 1
103 12
102 0
100 1
2
0 40 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__45 
6
2 0
1 1
0 1
103 7
102 9
100 1
2
0 69 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__450 
5
2 1
1 1
0 1
103 12
102 8
3
0 91 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__451 
6
2 1
1 1
0 1
103 12
102 8
100 1
2
0 91 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__452 
5
2 1
1 1
0 1
103 12
102 12
3
0 92 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__453 
6
2 1
1 1
0 1
103 12
102 12
100 1
2
0 92 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__454 
5
2 1
1 1
0 1
103 12
102 2
3
0 90 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__455 
6
2 1
1 1
0 1
103 12
102 2
100 1
2
0 90 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__456 
5
2 1
1 1
0 1
103 12
102 4
3
0 41 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__457 
6
2 1
1 1
0 1
103 12
102 4
100 1
2
0 41 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__458 
5
2 1
1 1
0 1
103 1
102 0
3
0 42 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__459 
6
2 1
1 1
0 1
103 1
102 0
100 1
2
0 42 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__46 
5
2 0
1 1
0 1
103 7
102 11
3
0 70 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__460 
5
2 1
1 1
0 1
103 1
102 5
3
0 94 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__461 
6
2 1
1 1
0 1
103 1
102 5
100 1
2
0 94 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__462 
5
2 1
1 1
0 1
103 1
102 6
3
0 95 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__463 
6
2 1
1 1
0 1
103 1
102 6
100 1
2
0 95 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__464 
5
2 1
1 1
0 1
103 1
102 8
3
0 96 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__465 
6
2 1
1 1
0 1
103 1
102 8
100 1
2
0 96 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__466 
5
2 1
1 1
0 1
103 1
102 9
3
0 97 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__467 
6
2 1
1 1
0 1
103 1
102 9
100 1
2
0 97 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__468 
5
2 1
1 1
0 1
103 1
102 10
3
0 98 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__469 
6
2 1
1 1
0 1
103 1
102 10
100 1
2
0 98 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__47 
6
2 0
1 1
0 1
103 7
102 11
100 1
2
0 70 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__470 
5
2 1
1 1
0 1
103 1
102 12
3
0 99 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__471 
6
2 1
1 1
0 1
103 1
102 12
100 1
2
0 99 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__472 
5
2 1
1 1
0 1
103 1
102 2
3
0 93 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__473 
6
2 1
1 1
0 1
103 1
102 2
100 1
2
0 93 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__474 
5
2 1
1 1
0 1
103 1
102 4
3
0 43 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__475 
6
2 1
1 1
0 1
103 1
102 4
100 1
2
0 43 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__476 
5
2 1
1 1
0 1
103 2
102 6
3
0 45 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__477 
6
2 1
1 1
0 1
103 2
102 6
100 1
2
0 45 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__478 
5
2 1
1 1
0 1
103 2
102 8
3
0 46 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__479 
6
2 1
1 1
0 1
103 2
102 8
100 1
2
0 46 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__48 
5
2 0
1 1
0 1
103 7
102 1
3
0 67 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__480 
5
2 1
1 1
0 1
103 2
102 12
3
0 47 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__481 
6
2 1
1 1
0 1
103 2
102 12
100 1
2
0 47 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__482 
5
2 1
1 1
0 1
103 2
102 2
3
0 44 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__483 
6
2 1
1 1
0 1
103 2
102 2
100 1
2
0 44 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__484 
5
2 1
1 1
0 1
103 2
102 4
3
0 16 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__485 
6
2 1
1 1
0 1
103 2
102 4
100 1
2
0 16 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__486 
5
2 1
1 1
0 1
103 3
102 0
3
0 17 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__487 
6
2 1
1 1
0 1
103 3
102 0
100 1
2
0 17 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__488 
5
2 1
1 1
0 1
103 3
102 5
3
0 49 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__489 
6
2 1
1 1
0 1
103 3
102 5
100 1
2
0 49 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__49 
6
2 0
1 1
0 1
103 7
102 1
100 1
2
0 67 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__490 
5
2 1
1 1
0 1
103 3
102 6
3
0 50 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__491 
6
2 1
1 1
0 1
103 3
102 6
100 1
2
0 50 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__492 
5
2 1
1 1
0 1
103 3
102 8
3
0 51 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__493 
6
2 1
1 1
0 1
103 3
102 8
100 1
2
0 51 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__494 
5
2 1
1 1
0 1
103 3
102 10
3
0 52 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__495 
6
2 1
1 1
0 1
103 3
102 10
100 1
2
0 52 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__496 
5
2 1
1 1
0 1
103 3
102 11
3
0 53 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__497 
6
2 1
1 1
0 1
103 3
102 11
100 1
2
0 53 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__498 
5
2 1
1 1
0 1
103 3
102 12
3
0 54 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__499 
6
2 1
1 1
0 1
103 3
102 12
100 1
2
0 54 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__5 
6
2 0
1 1
0 1
103 0
102 7
100 1
2
0 11 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__50 
5
2 0
1 1
0 1
103 8
102 0
3
0 73 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__500 
5
2 1
1 1
0 1
103 3
102 2
3
0 48 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__501 
6
2 1
1 1
0 1
103 3
102 2
100 1
2
0 48 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__502 
5
2 1
1 1
0 1
103 3
102 4
3
0 18 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__503 
6
2 1
1 1
0 1
103 3
102 4
100 1
2
0 18 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__504 
5
2 1
1 1
0 1
103 4
102 0
3
0 19 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__505 
6
2 1
1 1
0 1
103 4
102 0
100 1
2
0 19 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__506 
5
2 1
1 1
0 1
103 4
102 8
3
0 56 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__507 
6
2 1
1 1
0 1
103 4
102 8
100 1
2
0 56 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__508 
5
2 1
1 1
0 1
103 4
102 10
3
0 57 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__509 
6
2 1
1 1
0 1
103 4
102 10
100 1
2
0 57 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__51 
6
2 0
1 1
0 1
103 8
102 0
100 1
2
0 73 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__510 
5
2 1
1 1
0 1
103 4
102 2
3
0 55 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__511 
6
2 1
1 1
0 1
103 4
102 2
100 1
2
0 55 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__512 
5
2 1
1 1
0 1
103 4
102 4
3
0 20 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__513 
6
2 1
1 1
0 1
103 4
102 4
100 1
2
0 20 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__514 
5
2 3
1 1
0 1
103 0
102 0
3
0 30 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__515 
6
2 3
1 1
0 1
103 0
102 0
100 1
2
0 30 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__516 
5
2 3
1 1
0 1
103 0
102 6
3
0 58 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__517 
6
2 3
1 1
0 1
103 0
102 6
100 1
2
0 58 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__518 
5
2 3
1 1
0 1
103 0
102 12
3
0 59 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__519 
6
2 3
1 1
0 1
103 0
102 12
100 1
2
0 59 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__52 
5
2 0
1 1
0 1
103 8
102 5
3
0 74 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__520 
5
2 3
1 1
0 1
103 0
102 4
3
0 31 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__521 
6
2 3
1 1
0 1
103 0
102 4
100 1
2
0 31 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__522 
5
2 3
1 1
0 1
103 5
102 0
3
0 32 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__523 
6
2 3
1 1
0 1
103 5
102 0
100 1
2
0 32 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__524 
5
2 3
1 1
0 1
103 5
102 6
3
0 62 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__525 
6
2 3
1 1
0 1
103 5
102 6
100 1
2
0 62 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__526 
5
2 3
1 1
0 1
103 5
102 7
3
0 63 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__527 
6
2 3
1 1
0 1
103 5
102 7
100 1
2
0 63 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__528 
5
2 3
1 1
0 1
103 5
102 8
3
0 64 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__529 
6
2 3
1 1
0 1
103 5
102 8
100 1
2
0 64 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__53 
6
2 0
1 1
0 1
103 8
102 5
100 1
2
0 74 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__530 
5
2 3
1 1
0 1
103 5
102 10
3
0 65 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__531 
6
2 3
1 1
0 1
103 5
102 10
100 1
2
0 65 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__532 
5
2 3
1 1
0 1
103 5
102 12
3
0 66 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__533 
6
2 3
1 1
0 1
103 5
102 12
100 1
2
0 66 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__534 
5
2 3
1 1
0 1
103 5
102 2
3
0 60 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__535 
6
2 3
1 1
0 1
103 5
102 2
100 1
2
0 60 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__536 
5
2 3
1 1
0 1
103 5
102 3
3
0 61 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__537 
6
2 3
1 1
0 1
103 5
102 3
100 1
2
0 61 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__538 
5
2 3
1 1
0 1
103 5
102 4
3
0 33 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__539 
6
2 3
1 1
0 1
103 5
102 4
100 1
2
0 33 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__54 
5
2 0
1 1
0 1
103 8
102 6
3
0 75 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__540 
5
2 3
1 1
0 1
103 6
102 0
3
0 34 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__541 
6
2 3
1 1
0 1
103 6
102 0
100 1
2
0 34 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__542 
5
2 3
1 1
0 1
103 6
102 8
3
0 68 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__543 
6
2 3
1 1
0 1
103 6
102 8
100 1
2
0 68 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__544 
5
2 3
1 1
0 1
103 6
102 10
3
0 69 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__545 
6
2 3
1 1
0 1
103 6
102 10
100 1
2
0 69 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__546 
5
2 3
1 1
0 1
103 6
102 12
3
0 70 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__547 
6
2 3
1 1
0 1
103 6
102 12
100 1
2
0 70 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__548 
5
2 3
1 1
0 1
103 6
102 2
3
0 67 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__549 
6
2 3
1 1
0 1
103 6
102 2
100 1
2
0 67 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__55 
6
2 0
1 1
0 1
103 8
102 6
100 1
2
0 75 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__550 
5
2 3
1 1
0 1
103 7
102 0
3
0 35 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__551 
6
2 3
1 1
0 1
103 7
102 0
100 1
2
0 35 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__552 
5
2 3
1 1
0 1
103 7
102 5
3
0 73 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__553 
6
2 3
1 1
0 1
103 7
102 5
100 1
2
0 73 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__554 
5
2 3
1 1
0 1
103 7
102 6
3
0 74 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__555 
6
2 3
1 1
0 1
103 7
102 6
100 1
2
0 74 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__556 
5
2 3
1 1
0 1
103 7
102 7
3
0 75 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__557 
6
2 3
1 1
0 1
103 7
102 7
100 1
2
0 75 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__558 
5
2 3
1 1
0 1
103 7
102 8
3
0 76 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__559 
6
2 3
1 1
0 1
103 7
102 8
100 1
2
0 76 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__56 
5
2 0
1 1
0 1
103 8
102 7
3
0 76 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__560 
5
2 3
1 1
0 1
103 7
102 10
3
0 77 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__561 
6
2 3
1 1
0 1
103 7
102 10
100 1
2
0 77 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__562 
5
2 3
1 1
0 1
103 7
102 11
3
0 78 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__563 
6
2 3
1 1
0 1
103 7
102 11
100 1
2
0 78 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__564 
5
2 3
1 1
0 1
103 7
102 12
3
0 79 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__565 
6
2 3
1 1
0 1
103 7
102 12
100 1
2
0 79 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__566 
5
2 3
1 1
0 1
103 7
102 2
3
0 71 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__567 
6
2 3
1 1
0 1
103 7
102 2
100 1
2
0 71 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__568 
5
2 3
1 1
0 1
103 7
102 3
3
0 72 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__569 
6
2 3
1 1
0 1
103 7
102 3
100 1
2
0 72 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__57 
6
2 0
1 1
0 1
103 8
102 7
100 1
2
0 76 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__570 
5
2 3
1 1
0 1
103 7
102 4
3
0 36 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__571 
6
2 3
1 1
0 1
103 7
102 4
100 1
2
0 36 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__572 
5
2 3
1 1
0 1
103 8
102 10
3
0 80 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__573 
6
2 3
1 1
0 1
103 8
102 10
100 1
2
0 80 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__574 
5
2 3
1 1
0 1
103 8
102 4
3
0 37 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__575 
6
2 3
1 1
0 1
103 8
102 4
100 1
2
0 37 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__576 
5
2 3
1 1
0 1
103 9
102 0
3
0 38 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__577 
6
2 3
1 1
0 1
103 9
102 0
100 1
2
0 38 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__578 
5
2 3
1 1
0 1
103 9
102 5
3
0 83 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__579 
6
2 3
1 1
0 1
103 9
102 5
100 1
2
0 83 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__58 
5
2 0
1 1
0 1
103 8
102 9
3
0 77 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__580 
5
2 3
1 1
0 1
103 9
102 6
3
0 84 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__581 
6
2 3
1 1
0 1
103 9
102 6
100 1
2
0 84 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__582 
5
2 3
1 1
0 1
103 9
102 7
3
0 85 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__583 
6
2 3
1 1
0 1
103 9
102 7
100 1
2
0 85 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__584 
5
2 3
1 1
0 1
103 9
102 8
3
0 86 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__585 
6
2 3
1 1
0 1
103 9
102 8
100 1
2
0 86 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__586 
5
2 3
1 1
0 1
103 9
102 10
3
0 87 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__587 
6
2 3
1 1
0 1
103 9
102 10
100 1
2
0 87 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__588 
5
2 3
1 1
0 1
103 9
102 11
3
0 88 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__589 
6
2 3
1 1
0 1
103 9
102 11
100 1
2
0 88 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__59 
6
2 0
1 1
0 1
103 8
102 9
100 1
2
0 77 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__590 
5
2 3
1 1
0 1
103 9
102 12
3
0 89 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__591 
6
2 3
1 1
0 1
103 9
102 12
100 1
2
0 89 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__592 
5
2 3
1 1
0 1
103 9
102 2
3
0 81 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__593 
6
2 3
1 1
0 1
103 9
102 2
100 1
2
0 81 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__594 
5
2 3
1 1
0 1
103 9
102 3
3
0 82 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__595 
6
2 3
1 1
0 1
103 9
102 3
100 1
2
0 82 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__596 
5
2 3
1 1
0 1
103 9
102 4
3
0 39 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__597 
6
2 3
1 1
0 1
103 9
102 4
100 1
2
0 39 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__598 
5
2 3
1 1
0 1
103 10
102 0
3
0 40 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__599 
6
2 3
1 1
0 1
103 10
102 0
100 1
2
0 40 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__6 
5
2 0
1 1
0 1
103 0
102 8
3
0 12 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__60 
5
2 0
1 1
0 1
103 8
102 10
3
0 78 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__600 
5
2 3
1 1
0 1
103 10
102 8
3
0 91 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__601 
6
2 3
1 1
0 1
103 10
102 8
100 1
2
0 91 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__602 
5
2 3
1 1
0 1
103 10
102 12
3
0 92 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__603 
6
2 3
1 1
0 1
103 10
102 12
100 1
2
0 92 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__604 
5
2 3
1 1
0 1
103 10
102 2
3
0 90 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__605 
6
2 3
1 1
0 1
103 10
102 2
100 1
2
0 90 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__606 
5
2 3
1 1
0 1
103 10
102 4
3
0 41 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__607 
6
2 3
1 1
0 1
103 10
102 4
100 1
2
0 41 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__608 
5
2 3
1 1
0 1
103 11
102 0
3
0 42 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__609 
6
2 3
1 1
0 1
103 11
102 0
100 1
2
0 42 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__61 
6
2 0
1 1
0 1
103 8
102 10
100 1
2
0 78 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__610 
5
2 3
1 1
0 1
103 11
102 5
3
0 94 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__611 
6
2 3
1 1
0 1
103 11
102 5
100 1
2
0 94 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__612 
5
2 3
1 1
0 1
103 11
102 6
3
0 95 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__613 
6
2 3
1 1
0 1
103 11
102 6
100 1
2
0 95 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__614 
5
2 3
1 1
0 1
103 11
102 8
3
0 96 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__615 
6
2 3
1 1
0 1
103 11
102 8
100 1
2
0 96 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__616 
5
2 3
1 1
0 1
103 11
102 9
3
0 97 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__617 
6
2 3
1 1
0 1
103 11
102 9
100 1
2
0 97 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__618 
5
2 3
1 1
0 1
103 11
102 10
3
0 98 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__619 
6
2 3
1 1
0 1
103 11
102 10
100 1
2
0 98 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__62 
5
2 0
1 1
0 1
103 8
102 11
3
0 79 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__620 
5
2 3
1 1
0 1
103 11
102 12
3
0 99 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__621 
6
2 3
1 1
0 1
103 11
102 12
100 1
2
0 99 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__622 
5
2 3
1 1
0 1
103 11
102 2
3
0 93 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__623 
6
2 3
1 1
0 1
103 11
102 2
100 1
2
0 93 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__624 
5
2 3
1 1
0 1
103 11
102 4
3
0 43 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__625 
6
2 3
1 1
0 1
103 11
102 4
100 1
2
0 43 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__626 
5
2 3
1 1
0 1
103 12
102 6
3
0 45 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__627 
6
2 3
1 1
0 1
103 12
102 6
100 1
2
0 45 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__628 
5
2 3
1 1
0 1
103 12
102 8
3
0 46 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__629 
6
2 3
1 1
0 1
103 12
102 8
100 1
2
0 46 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__63 
6
2 0
1 1
0 1
103 8
102 11
100 1
2
0 79 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__630 
5
2 3
1 1
0 1
103 12
102 12
3
0 47 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__631 
6
2 3
1 1
0 1
103 12
102 12
100 1
2
0 47 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__632 
5
2 3
1 1
0 1
103 12
102 2
3
0 44 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__633 
6
2 3
1 1
0 1
103 12
102 2
100 1
2
0 44 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__634 
5
2 3
1 1
0 1
103 12
102 4
3
0 16 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__635 
6
2 3
1 1
0 1
103 12
102 4
100 1
2
0 16 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__636 
5
2 3
1 1
0 1
103 1
102 0
3
0 17 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__637 
6
2 3
1 1
0 1
103 1
102 0
100 1
2
0 17 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__638 
5
2 3
1 1
0 1
103 1
102 5
3
0 49 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__639 
6
2 3
1 1
0 1
103 1
102 5
100 1
2
0 49 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__64 
5
2 0
1 1
0 1
103 8
102 1
3
0 71 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__640 
5
2 3
1 1
0 1
103 1
102 6
3
0 50 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__641 
6
2 3
1 1
0 1
103 1
102 6
100 1
2
0 50 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__642 
5
2 3
1 1
0 1
103 1
102 8
3
0 51 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__643 
6
2 3
1 1
0 1
103 1
102 8
100 1
2
0 51 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__644 
5
2 3
1 1
0 1
103 1
102 10
3
0 52 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__645 
6
2 3
1 1
0 1
103 1
102 10
100 1
2
0 52 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__646 
5
2 3
1 1
0 1
103 1
102 11
3
0 53 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__647 
6
2 3
1 1
0 1
103 1
102 11
100 1
2
0 53 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__648 
5
2 3
1 1
0 1
103 1
102 12
3
0 54 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__649 
6
2 3
1 1
0 1
103 1
102 12
100 1
2
0 54 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__65 
6
2 0
1 1
0 1
103 8
102 1
100 1
2
0 71 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__650 
5
2 3
1 1
0 1
103 1
102 2
3
0 48 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__651 
6
2 3
1 1
0 1
103 1
102 2
100 1
2
0 48 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__652 
5
2 3
1 1
0 1
103 1
102 4
3
0 18 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__653 
6
2 3
1 1
0 1
103 1
102 4
100 1
2
0 18 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__654 
5
2 3
1 1
0 1
103 2
102 0
3
0 19 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__655 
6
2 3
1 1
0 1
103 2
102 0
100 1
2
0 19 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__656 
5
2 3
1 1
0 1
103 2
102 8
3
0 56 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__657 
6
2 3
1 1
0 1
103 2
102 8
100 1
2
0 56 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__658 
5
2 3
1 1
0 1
103 2
102 10
3
0 57 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__659 
6
2 3
1 1
0 1
103 2
102 10
100 1
2
0 57 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__66 
5
2 0
1 1
0 1
103 8
102 2
3
0 72 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__660 
5
2 3
1 1
0 1
103 2
102 2
3
0 55 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__661 
6
2 3
1 1
0 1
103 2
102 2
100 1
2
0 55 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__662 
5
2 3
1 1
0 1
103 2
102 4
3
0 20 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__663 
6
2 3
1 1
0 1
103 2
102 4
100 1
2
0 20 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__664 
5
2 3
1 1
0 1
103 3
102 0
3
0 5 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__665 
6
2 3
1 1
0 1
103 3
102 0
100 1
2
0 5 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__666 
5
2 3
1 1
0 1
103 3
102 5
3
0 23 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__667 
6
2 3
1 1
0 1
103 3
102 5
100 1
2
0 23 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__668 
5
2 3
1 1
0 1
103 3
102 6
3
0 24 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__669 
6
2 3
1 1
0 1
103 3
102 6
100 1
2
0 24 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__67 
6
2 0
1 1
0 1
103 8
102 2
100 1
2
0 72 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__670 
5
2 3
1 1
0 1
103 3
102 8
3
0 25 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__671 
6
2 3
1 1
0 1
103 3
102 8
100 1
2
0 25 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__672 
5
2 3
1 1
0 1
103 3
102 9
3
0 26 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__673 
6
2 3
1 1
0 1
103 3
102 9
100 1
2
0 26 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__674 
5
2 3
1 1
0 1
103 3
102 10
3
0 27 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__675 
6
2 3
1 1
0 1
103 3
102 10
100 1
2
0 27 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__676 
5
2 3
1 1
0 1
103 3
102 11
3
0 28 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__677 
6
2 3
1 1
0 1
103 3
102 11
100 1
2
0 28 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__678 
5
2 3
1 1
0 1
103 3
102 12
3
0 29 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__679 
6
2 3
1 1
0 1
103 3
102 12
100 1
2
0 29 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__68 
5
2 0
1 1
0 1
103 8
102 3
3
0 36 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__680 
5
2 3
1 1
0 1
103 3
102 1
3
0 21 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__681 
6
2 3
1 1
0 1
103 3
102 1
100 1
2
0 21 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__682 
5
2 3
1 1
0 1
103 3
102 2
3
0 22 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__683 
6
2 3
1 1
0 1
103 3
102 2
100 1
2
0 22 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__684 
5
2 3
1 1
0 1
103 3
102 4
3
0 6 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__685 
6
2 3
1 1
0 1
103 3
102 4
100 1
2
0 6 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__69 
6
2 0
1 1
0 1
103 8
102 3
100 1
2
0 36 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__7 
6
2 0
1 1
0 1
103 0
102 8
100 1
2
0 12 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__70 
5
2 0
1 1
0 1
103 9
102 9
3
0 80 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__71 
6
2 0
1 1
0 1
103 9
102 9
100 1
2
0 80 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__72 
5
2 0
1 1
0 1
103 9
102 3
3
0 37 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__73 
6
2 0
1 1
0 1
103 9
102 3
100 1
2
0 37 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__74 
5
2 0
1 1
0 1
103 10
102 0
3
0 83 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__75 
6
2 0
1 1
0 1
103 10
102 0
100 1
2
0 83 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__76 
5
2 0
1 1
0 1
103 10
102 5
3
0 84 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__77 
6
2 0
1 1
0 1
103 10
102 5
100 1
2
0 84 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__78 
5
2 0
1 1
0 1
103 10
102 6
3
0 85 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__79 
6
2 0
1 1
0 1
103 10
102 6
100 1
2
0 85 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__8 
5
2 0
1 1
0 1
103 0
102 9
3
0 13 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__80 
5
2 0
1 1
0 1
103 10
102 7
3
0 86 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__81 
6
2 0
1 1
0 1
103 10
102 7
100 1
2
0 86 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__82 
5
2 0
1 1
0 1
103 10
102 9
3
0 87 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__83 
6
2 0
1 1
0 1
103 10
102 9
100 1
2
0 87 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__84 
5
2 0
1 1
0 1
103 10
102 10
3
0 88 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__85 
6
2 0
1 1
0 1
103 10
102 10
100 1
2
0 88 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__86 
5
2 0
1 1
0 1
103 10
102 11
3
0 89 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__87 
6
2 0
1 1
0 1
103 10
102 11
100 1
2
0 89 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__88 
5
2 0
1 1
0 1
103 10
102 1
3
0 81 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__89 
6
2 0
1 1
0 1
103 10
102 1
100 1
2
0 81 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__9 
6
2 0
1 1
0 1
103 0
102 9
100 1
2
0 13 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__90 
5
2 0
1 1
0 1
103 10
102 2
3
0 82 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__91 
6
2 0
1 1
0 1
103 10
102 2
100 1
2
0 82 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__92 
5
2 0
1 1
0 1
103 10
102 3
3
0 39 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__93 
6
2 0
1 1
0 1
103 10
102 3
100 1
2
0 39 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__94 
5
2 0
1 1
0 1
103 11
102 7
3
0 91 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__95 
6
2 0
1 1
0 1
103 11
102 7
100 1
2
0 91 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__96 
5
2 0
1 1
0 1
103 11
102 11
3
0 92 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__97 
6
2 0
1 1
0 1
103 11
102 11
100 1
2
0 92 0 1
0 101 2 1
1
end_operator
begin_operator
place_block__98 
5
2 0
1 1
0 1
103 11
102 1
3
0 90 0 1
0 100 1 0
0 101 1 0
1
end_operator
begin_operator
place_block__99 
6
2 0
1 1
0 1
103 11
102 1
100 1
2
0 90 0 1
0 101 2 1
1
end_operator
begin_operator
rotate_left__0 
0
1
0 2 0 3
1
end_operator
begin_operator
rotate_left__1 
0
1
0 2 1 0
1
end_operator
begin_operator
rotate_left__2 
0
1
0 2 2 1
1
end_operator
begin_operator
rotate_left__3 
0
1
0 2 3 2
1
end_operator
begin_operator
rotate_right__0 
0
1
0 2 0 1
1
end_operator
begin_operator
rotate_right__1 
0
1
0 2 1 2
1
end_operator
begin_operator
rotate_right__2 
0
1
0 2 2 3
1
end_operator
begin_operator
rotate_right__3 
0
1
0 2 3 0
1
end_operator
0
