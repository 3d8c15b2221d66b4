// The hybrid map views' colours (levels_view.frag, scene_view.frag): level 0 (full resolution) red,
// 1 yellow, 2 green, 3 blue; steps per lookup 0 blue, 1 green, 2 orange, 3 red.
const vec3 HYBRID_LEVEL_COLOURS[4] = vec3[](vec3(0.90, 0.22, 0.16), vec3(0.95, 0.80, 0.20), vec3(0.30, 0.78, 0.32),
                                            vec3(0.30, 0.50, 0.95));
const vec3 HYBRID_STEP_COLOURS[4] = vec3[](vec3(0.25, 0.45, 0.95), vec3(0.30, 0.78, 0.32), vec3(0.98, 0.60, 0.15),
                                           vec3(0.90, 0.15, 0.12));
