// Included by lit.frag: a test of a name in an include file counts only through the stages that
// include it.
float shadow() {
#if defined(SOFT) && SOFT > 1
  return 0.5;
#else
  return 1.0;
#endif
}
