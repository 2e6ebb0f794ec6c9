/* The camera/ parity cases' shared part (the cases are described in
   tests/parity/camera_cases.cpp). Depth conventions and integer pixel values
   arrive as integral floats (the generators never send NaN there: int(NaN) is
   undefined). Matrices are built from a camera (fovy, aspect, zNear, zFar) with
   snellPerspectiveWithDepth, the same way on both sides, and leave as their
   four columns. */
#include "snell/camera.glsl"

SNELL_FN mat4 cameraParityMatrix(vec4 camera, int convention) {
  return snellPerspectiveWithDepth(camera.x, camera.y, camera.z, camera.w, convention);
}

/* Sets the outputs column0..column3 (CAMERA_COLUMNS_OUT) to the columns of m. */
#define CAMERA_PARITY_SET_COLUMNS(m)                                    \
  mat4 cameraParityM = m;                                               \
  column0 = SNELL_MUL(cameraParityM, vec4(1.0f, 0.0f, 0.0f, 0.0f));     \
  column1 = SNELL_MUL(cameraParityM, vec4(0.0f, 1.0f, 0.0f, 0.0f));     \
  column2 = SNELL_MUL(cameraParityM, vec4(0.0f, 0.0f, 1.0f, 0.0f));     \
  column3 = SNELL_MUL(cameraParityM, vec4(0.0f, 0.0f, 0.0f, 1.0f))

SNELL_FN SnellTexRay cameraParityTexRay(vec4 camera, int convention, vec3 p1, vec3 t1, float zNearest,
                                        float zFarthest) {
  return snellTexRaySetup(p1, t1, zNearest, zFarthest, cameraParityMatrix(camera, convention));
}
