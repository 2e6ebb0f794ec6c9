/*
description: the buffers a two-interface technique reads, as the parameter
  lists every technique function declares and the argument lists every call
  inside snell passes on. A layer of buffers is a depth texture, its
  view-space normals, its depth min/max pyramid where a strategy needs one,
  and the SnellDepthSurface that says how to read them; the object's layers
  (its back faces and its front faces) and the opaque scene's (its layer,
  its colour and the environment) each travel as one list, so a new layer
  (a second back-face layer) is one edit here, not one per function and
  call site inside snell.
use: in a function that takes or forwards the buffers:
     SNELL_FN SnellTwoInterfacePath f(vec3 p, SNELL_OBJECT_BUFFERS, SNELL_SCENE_BUFFERS) {
       return g(p, SNELL_OBJECT_BUFFER_ARGS, SNELL_SCENE_BUFFER_ARGS);
     }
     A caller outside snell passes its own textures in the order below.
options:
  SNELL_OBJECT_BUFFERS  SNELL_TEX2D backDepth, SNELL_TEX2D backNormal,
                        SNELL_TEX2D backPyramid, SnellDepthSurface back
                        (the back-face pass: depth cleared to the near value
                        and drawn with GL_GREATER, view-space normals, the
                        pyramid of that depth, how to read the depth),
                        SNELL_TEX2D frontLayerDepth, SNELL_TEX2D
                        frontLayerNormal, SnellDepthSurface frontLayer (the
                        front-face pass: depth
                        cleared to the far value and drawn with GL_LESS,
                        view-space normals, how to read the depth; read only
                        by rays that bounce inside, SnellTechnique.bounces >
                        0: any texture of the right kind may be bound when
                        bounces is 0)
  SNELL_SCENE_BUFFERS   SNELL_TEX2D sceneDepth, SNELL_TEX2D sceneNormal,
                        SNELL_TEX2D scenePyramid, SNELL_TEX2D sceneColor,
                        SnellDepthSurface scene, SNELL_ENVIRONMENT_TEX
                        environment (the opaque scene without the object,
                        its colour, mipmapped for roughness > 0, and the
                        distant environment)
  SNELL_OBJECT_BUFFER_ARGS, SNELL_SCENE_BUFFER_ARGS  the same names as
                        arguments, for the call sites inside snell.
contract: macros only, each on one line (GLSL 330 has no line continuation). Why parameter lists and not a struct of samplers:
  GLSL allows a struct holding samplers only as a uniform (no constructor, so
  a shader could not group textures it declared apart), Vulkan GLSL cannot
  give such a struct's members explicit bindings, WGSL has no structs of
  textures, and GLSL ES has no token pasting for a per-layer name prefix.
  A fixed list of names compiles in every language snell runs, and the code
  after the preprocessor is the code written out by hand (no cost on any
  runtime).
*/
#ifndef SNELL_SHADE_TECHNIQUE_BUFFERS_GLSL
#define SNELL_SHADE_TECHNIQUE_BUFFERS_GLSL
#include "../prelude.glsl"
#include "../intersect/depth_surface.glsl"
#include "environment.glsl"

#define SNELL_OBJECT_BUFFERS SNELL_TEX2D backDepth, SNELL_TEX2D backNormal, SNELL_TEX2D backPyramid, SNELL_IN(SnellDepthSurface) back, SNELL_TEX2D frontLayerDepth, SNELL_TEX2D frontLayerNormal, SNELL_IN(SnellDepthSurface) frontLayer
#define SNELL_OBJECT_BUFFER_ARGS backDepth, backNormal, backPyramid, back, frontLayerDepth, frontLayerNormal, frontLayer

#define SNELL_SCENE_BUFFERS SNELL_TEX2D sceneDepth, SNELL_TEX2D sceneNormal, SNELL_TEX2D scenePyramid, SNELL_TEX2D sceneColor, SNELL_IN(SnellDepthSurface) scene, SNELL_ENVIRONMENT_TEX environment
#define SNELL_SCENE_BUFFER_ARGS sceneDepth, sceneNormal, scenePyramid, sceneColor, scene, environment

#endif
