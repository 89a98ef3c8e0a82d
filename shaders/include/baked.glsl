// A scene's static parameters as specialisation constants
// (src/passes/raymarch/baked.rs; the values and their ids from the one
// table src/passes/raymarch/baked_table.rs, checked by tests/layout.rs
// against every SPIR-V module).
// An offscreen render compiles them into its ray march (BAKED), where the
// driver folds them: a hole at the origin, a disk normal along y, a switch
// that is off take their products by 0 and 1 and their branches away, and
// no register holds them across the shader (a CPU driver spills what it
// cannot keep: about a quarter of the trace pass's instructions were
// moves to and from the stack). The window, whose panel changes them
// between frames, reads them from the parameter block (BAKED false). What
// changes from frame to frame (the camera, the observer, the disk's
// turn) always comes from the block.
#ifndef BAKED_GLSL
#define BAKED_GLSL

// Written by build.rs from src/passes/raymarch/baked_table.rs: the switch
// `layout(constant_id = FIRST) const bool BAKED = false;`, a
// `layout(constant_id = FIRST + 1 + i) const float NAME = 0.0;` line for
// each row i, then `void bake_params()`, which overwrites the block's copy
// `P` with them (a no-op unless BAKED).
#include "baked_values.glsl"

#endif
