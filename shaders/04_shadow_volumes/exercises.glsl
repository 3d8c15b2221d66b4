// Lesson 04, GLSL exercise: YOUR extrusion to infinity, written in the shader. With impl=student and
// silhouettes=gpu, the volumes' geometry shader (shaders/04_shadow_volumes/volume.geom) sends every
// vertex of a volume that lies at infinity through this function: the far ends of the silhouette
// quads and the far caps of z-fail:
//   lesson_04_shadow_volumes --set impl=student --preset silhouettes_gpu
// (the file reloads by itself when you save it; a compile error shows in the header, file:line).
// Grade: make grade LESSON=04 (it builds what changed first; the GLSL cases run on the GPU, headless, and the
// lesson renders with your shader against the reference). The stub compiles and returns the point
// itself: the volumes have no length and nothing is shadowed. Delete its SHADOWLAB_STUB line when
// you write it.

// EXERCISE 04.5 (GLSL): the point at infinity of a shadow volume ([Everitt2002],
// [Tarantsev-L12]). p is a world-space vertex of a caster's silhouette (or of a face that caps
// the volume); light is the light in homogeneous form: (position, 1) for a point or spot light,
// (-direction, 0) for a directional one (so light.xyz points from the scene toward the light).
// Return, in world-space homogeneous coordinates, the point at infinity where the ray from the
// light through p ends: w = 0 and xyz the direction away from the light along that ray (from the
// light's position through p; for a directional light its direction, the same for every p). The
// shader multiplies it by the view-projection matrix; with the infinite far plane (exercise 04.2)
// it projects inside the view volume. One expression covers both kinds of light.
vec4 extrudeToInfinity(vec3 p, vec4 light) {
  // SHADOWLAB_STUB 04.5: delete this line when you write the exercise
  return vec4(p, 1.0);
}
