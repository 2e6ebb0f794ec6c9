/* The probes of each parity runtime's float rules (tests/parity/runtime_floats_test.cpp): plain
   arithmetic on chosen floats, nothing of snell's but the language bridge. */
#include "snell/prelude.glsl"
