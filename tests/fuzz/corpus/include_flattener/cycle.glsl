#version 330 core
#include "a.glsl"
@@@
#include "b.glsl"
@@@
#include "a.glsl"
