// All of snell's C++ API: the same functions as glsl/snell/snell.glsl.
#pragma once
#include "bridge.hpp"
#include "camera.hpp"
#include "intersect.hpp"
#include "optics.hpp"
