#version 410 core
// The squashed scene, flat-shaded from screen derivatives (normals do not survive a projective map),
// coloured by post-projective depth (warm at the near face, cool at the far one, so the crowding of
// the distance toward the far face shows), tinted red where it lies behind the camera.
in vec4 vView;
in vec2 vDepth;
uniform vec3 uAlbedo;
uniform float uSign;
layout(location = 0) out vec4 fragColor;
#ifdef SHADOWLAB_NO_CLIP_DISTANCE
in float vClip[7];  // post_projective.vert's clip distances, tested here (WebGL2)
#endif

void main() {
#ifdef SHADOWLAB_NO_CLIP_DISTANCE
  for (int k = 0; k < 7; ++k)
    if (vClip[k] < 0.0) discard;
#endif
  vec3 p = vView.xyz / vView.w;
  vec3 n = normalize(cross(dFdx(p), dFdy(p)));
  float shade = 0.35 + 0.65 * abs(n.z);
  float z = clamp(0.5 * vDepth.x / vDepth.y + 0.5, 0.0, 1.0);
  vec3 ramp = mix(vec3(1.0, 0.72, 0.45), vec3(0.5, 0.7, 1.0), z);
  vec3 c = mix(uAlbedo, vec3(1.0), 0.3) * ramp * shade;
  if (uSign < 0.0) c = mix(c, vec3(1.0, 0.3, 0.25), 0.55);
  fragColor = vec4(c, 1.0);
}
