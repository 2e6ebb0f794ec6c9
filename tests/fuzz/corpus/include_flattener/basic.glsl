#version 450 core
#extension GL_GOOGLE_include_directive : require
#include "a.glsl"
#include <e.glsl>
void main() { x = f(); }
@@@
#ifndef A
#define A
#include "b.glsl"
float f() { return g(); }
#endif
@@@
float g() { return 1.0; }
@@@
@@@
@@@
/* comment #include "zzz" */
int e;
