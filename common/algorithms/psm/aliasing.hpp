#pragma once
// Closed-form perspective aliasing along view depth, for the lessons' plots. The standard set-up
// (Stamminger & Drettakis 2002, Wimmer et al. 2004, Lloyd et al. 2008): a directional light
// perpendicular to the view direction, the map's s in [0,1] parameterising view depth z in
// [zn, zf]. A texel covers dz/ds / res of depth, a screen pixel covers ~ z / res', so the
// aliasing factor is  m(z) = (dz/ds) / z  (up to the constant ratio of resolutions and the
// field of view). Lower is better; a constant m is the ideal (logarithmic).
//   uniform      s = (z - zn)/(zf - zn)                  m = (zf - zn) / z
//   PSM          s = (1/zn - 1/z)/(1/zn - 1/zf)          m = z (zf - zn) / (zn zf)
//   LiSPSM(n)    PSM's s with z' = z - zn + n            m = z'^2 (1/n - 1/(zf - zn + n)) / z
//   logarithmic  s = ln(z/zn)/ln(zf/zn)                  m = ln(zf/zn)
// LiSPSM with n = zn is PSM, n -> inf is uniform, n = zn + sqrt(zn zf) equalises m(zn) and m(zf).

namespace shadowlab::psm {

enum class Parameterisation { Uniform, Psm, Lispsm, Logarithmic };

// m(z) as above. lispsmN is used only for Lispsm (0 means the optimum zn + sqrt(zn zf)).
// Throws std::invalid_argument for zn <= 0, zf <= zn, z outside [zn, zf] or lispsmN < 0.
double perspectiveAliasing(Parameterisation p, double z, double zNear, double zFar, double lispsmN = 0.0);

// s(z) itself (in [0,1]), so a lesson can plot texel distribution next to m.
double shadowMapCoordinate(Parameterisation p, double z, double zNear, double zFar, double lispsmN = 0.0);

}  // namespace shadowlab::psm
