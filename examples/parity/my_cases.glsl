/* The parity case of myTwoSurfaceTransmittance: the fixed entry shape
   SnellParityOut entry(vec4, vec4, vec4, vec4) that snell's parity runner
   calls once per input, on the GPU and (this very text) in C++. */
#include "my_transmittance.glsl"

SNELL_FN SnellParityOut caseMyTransmittance(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  float t = myTwoSurfaceTransmittance(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z), c.x);
  o.a = vec4(t, 0.0f, 0.0f, 0.0f);
  o.b = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  o.c = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  o.d = d * 0.0f;
  return o;
}
