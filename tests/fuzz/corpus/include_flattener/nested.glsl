#include "sub/e.glsl"
#include bad
@@@
@@@
@@@
@@@
@@@
#include "f.glsl"
#include "../a.glsl"
@@@
#version 100
void f(){}
