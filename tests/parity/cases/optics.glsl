/* The optics/ parity cases' shared part (the cases themselves are described in
   tests/parity/optics_cases.cpp): the family's include. */
#include "snell/optics.glsl"
