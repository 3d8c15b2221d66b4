// Deliberately invalid helper for shader_check's tests: the error on line 3 must be reported
// against this file, not against the shader that includes it.
float brokenHelper() { return missingValue; }
