#pragma once
// Per-attachment colour masks and blending (OpenGL 3.0 / 4.0 core). Attachment 0 is the picture,
// 1-3 the ground truth's surfaces (app/measurement.hpp). WebGL2 has neither call and no ground
// truth: there attachment 0's mask is the whole framebuffer's, and the others are left alone.
#include "gl/caps.hpp"
#include "gl/gl.hpp"

namespace shadowlab::gl {

inline void colorMaskAttachment(GLuint attachment, bool on) {
  const GLboolean b = on ? GL_TRUE : GL_FALSE;
  if (!caps().gles) glColorMaski(attachment, b, b, b, b);
  else if (attachment == 0) glColorMask(b, b, b, b);
}

inline void disableBlendAttachment(GLuint attachment) {
  if (!caps().gles) glDisablei(GL_BLEND, attachment);
}

}  // namespace shadowlab::gl
