// Outputs for measuring a shadow technique against ground truth (common/app/measurement.cpp).
// A lesson's scene fragment shader includes this and calls writeMeasurement() once. When the frame
// is rendered into the framework's measurement target, these land in attachments 1-3; on a plain
// framebuffer they have no draw buffer and cost nothing.
//   1: world position (the ray origins: the very points this shader shaded)
//   2: unit normal, and in .w the technique's visibility V of the measured light (0..1)
//   3: the Jacobian of shadow-map texel coordinates per screen pixel (dFdx, dFdy), 0 when none
layout(location = 1) out vec4 outMeasurePosition;
layout(location = 2) out vec4 outMeasureNormal;
layout(location = 3) out vec4 outMeasureJacobian;

// Which light the framework measures (lessons pass it through; -1 when measurement is off).
uniform int uMeasureLight;

// `shadowTexel`: the shadow-map texel coordinates of this pixel (uv * map size), or vec2(0) for a
// technique without a map.
void writeMeasurement(vec3 worldPos, vec3 N, float visibility, vec2 shadowTexel) {
  outMeasurePosition = vec4(worldPos, 1.0);
  outMeasureNormal = vec4(normalize(N), visibility);
  outMeasureJacobian = vec4(dFdx(shadowTexel), dFdy(shadowTexel));
}

// The same with the Jacobian given (du/dx, dv/dx, du/dy, dv/dy in texels): for a technique whose
// texel coordinates jump between the pixels of a 2x2 quad (the cascades, where the quad straddles
// two maps), so that dFdx of them would measure the jump, not the map (SHADOW_TEXEL_JACOBIAN).
void writeMeasurementJacobian(vec3 worldPos, vec3 N, float visibility, vec4 jacobian) {
  outMeasurePosition = vec4(worldPos, 1.0);
  outMeasureNormal = vec4(normalize(N), visibility);
  outMeasureJacobian = jacobian;
}

// For everything that is not a measured surface (gizmos, debug lines, overlays): GL leaves an output
// a shader does not write undefined, so such shaders must clear them explicitly.
void writeNoMeasurement() {
  outMeasurePosition = vec4(0.0);
  outMeasureNormal = vec4(0.0);
  outMeasureJacobian = vec4(0.0);
}
