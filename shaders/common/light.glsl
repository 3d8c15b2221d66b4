// A light as every shader sees it (common/core/light.hpp on the CPU). Just the declarations, so a
// technique's own fragment shader, linked beside a lit shader, can read uLights[] without a second
// copy of the functions in lighting.glsl (a program may define each function only once).
const int LIGHT_POINT = 0;
const int LIGHT_SPOT = 1;
const int LIGHT_DIRECTIONAL = 2;
const int MAX_LIGHTS = 4;

struct Light {
  int kind;
  bool enabled;
  vec3 position;     // point, spot
  vec3 direction;    // spot axis, directional travel direction (unit)
  vec3 color;        // colour times intensity
  vec3 attenuation;  // c0, c1, c2
  float cosInner, cosOuter;
};
