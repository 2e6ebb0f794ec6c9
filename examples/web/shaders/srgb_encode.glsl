// Linear RGB, clamped to [0, 1], to the sRGB transfer curve (IEC 61966-2-1): what the 8-bit canvas shows.
vec3 pageEncodeSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  vec3 lo = 12.92 * c;
  vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(lo, hi, step(vec3(0.0031308), c));
}
