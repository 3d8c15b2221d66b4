// Lesson 09, GLSL exercise: YOUR choice of the face map (fix 3), written in the shader. With
// impl=student and face maps in use (fix.faces=always, or auto when the cone is too wide), the PSM
// technique (shaders/08_psm/shadow_psm.frag) picks every pixel's map with this function:
//   lesson_09_psm_fixes --set impl=student --preset faces_always
// (the file reloads by itself when you save it; a compile error shows in the header, file:line).
// Grade: make grade LESSON=09 (it builds what changed first; the GLSL cases run on the GPU, headless, and the
// lesson renders with your shader against the reference). The stub compiles and returns a neutral
// value; delete its SHADOWLAB_STUB line when you write it.

// EXERCISE 09.6 (GLSL): the face a point is looked up through ([Kozlov2004] §4.2). Fix 3 renders
// one map on each face of the camera's unit cube [-1,1]^3 that the light does not see (exercise
// 09.3). A point q (post-projective, inside the cube) is in the map of the face through which the
// light's ray through q LEAVES the cube: the ray o + t v from o = the light's position along
// v = q - position (light = (position, 1)), or, for a light that is a direction (light = (d, 0)),
// from o = q along v = -d. Faces: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z; face f has the outward normal
// n_f and lies in dot(n_f, x) = 1. Among the faces that hold a map (layerOfFace[f] >= 0) and that
// the ray crosses outward (dot(n_f, v) > 0), the one it reaches first (the smallest
// t = (1 - dot(n_f, o)) / dot(n_f, v)) is where it leaves. Return that face's layer,
// layerOfFace[f], or -1 when there is none (the lesson calls the point lit).
int cubeFaceLayer(vec3 q, vec4 light, int layerOfFace[6]) {
  // SHADOWLAB_STUB 09.6: delete this line when you write the exercise
  return -1;
}
