0:12(5): error: x undeclared
ERROR: 1:3: foo
0(1000004) : error C0000
@@@
int a;
