#version 410 core
// Stencil shadow volumes (lessons/04_shadow_volumes/stencil_volumes, lesson 04), pass 2 on the GPU:
// silhouettes with GL_TRIANGLES_ADJACENCY (core since 3.2). Each input is a triangle (0, 2, 4) with
// the far vertex of each neighbour (1, 3, 5). A triangle toward the light emits a quad to infinity
// on each edge whose neighbour is turned away (the same rule as algorithms/shadow_volume.cpp, so
// the CPU and GPU volumes agree); a triangle turned away emits the two caps when z-fail needs them.
// An open edge's "neighbour" is the triangle's own third vertex, which makes it a silhouette edge
// of a lit face, like the CPU path. uTwoSided (open meshes): a face turned away casts as if flipped,
// emitting the reversed quad on each edge whose neighbour is toward the light (or open), as
// findSilhouette(..., twoSided) does.
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 18) out;

in vec3 vWorld[];
uniform mat4 uViewProj;
uniform vec4 uLight;  // (position, 1) or (-direction, 0)
uniform bool uCaps;
uniform bool uTwoSided;

bool facesLight(vec3 a, vec3 b, vec3 c) {
  return dot(cross(b - a, c - a), uLight.xyz - a * uLight.w) > 0.0;
}
// The extrusion, extrudeToInfinity(p, light): exercise 04.5 (GLSL). The student's with
// impl=student in lesson 04 (StencilVolumes::student.glslExtrusion builds this shader with
// SHADOWLAB_STUDENT_GLSL), else the reference (withheld from the student handout).
#ifdef SHADOWLAB_STUDENT_GLSL
#include "04_shadow_volumes/exercises.glsl"
#else
#include "04_shadow_volumes/exercises_reference.glsl"
#endif

vec4 atInfinity(vec3 p) { return uViewProj * extrudeToInfinity(p, uLight); }
vec4 onCaster(vec3 p) { return uViewProj * vec4(p, 1.0); }

void main() {
  vec3 v[6];
  for (int i = 0; i < 6; ++i) v[i] = vWorld[i];
  if (facesLight(v[0], v[2], v[4])) {
    for (int k = 0; k < 3; ++k) {
      vec3 a = v[2 * k], b = v[(2 * k + 2) % 6], d = v[2 * k + 1];
      if (facesLight(b, a, d)) continue;
      // The quad (b, a, a_inf, b_inf) as a strip: b, a, b_inf, a_inf.
      gl_Position = onCaster(b); EmitVertex();
      gl_Position = onCaster(a); EmitVertex();
      gl_Position = atInfinity(b); EmitVertex();
      gl_Position = atInfinity(a); EmitVertex();
      EndPrimitive();
    }
  } else if (uTwoSided) {
    for (int k = 0; k < 3; ++k) {
      vec3 a = v[2 * k], b = v[(2 * k + 2) % 6], d = v[2 * k + 1];
      if (!facesLight(b, a, d)) continue;
      // The flipped face walks b -> a: the quad (a, b, b_inf, a_inf) as a strip.
      gl_Position = onCaster(a); EmitVertex();
      gl_Position = onCaster(b); EmitVertex();
      gl_Position = atInfinity(a); EmitVertex();
      gl_Position = atInfinity(b); EmitVertex();
      EndPrimitive();
    }
  } else if (uCaps) {
    gl_Position = onCaster(v[0]); EmitVertex();  // near cap, reversed
    gl_Position = onCaster(v[4]); EmitVertex();
    gl_Position = onCaster(v[2]); EmitVertex();
    EndPrimitive();
    gl_Position = atInfinity(v[0]); EmitVertex();  // far cap
    gl_Position = atInfinity(v[2]); EmitVertex();
    gl_Position = atInfinity(v[4]); EmitVertex();
    EndPrimitive();
  }
}
