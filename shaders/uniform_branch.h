// Branches on uniform values that the driver must not specialise the shader on.
//
// lavapipe (Mesa 22.3) "inlines uniforms": when a shader's branch conditions depend on uniform-buffer
// or push-constant values alone, it folds the bound values in and compiles the shader again with LLVM
// after a descriptor bind, and keeps doing so while the folded shader is much smaller. The density and
// splat passes qualified (their object flags and print-detail switch): two LLVM compiles in every frame,
// 3-5 ms of a 10-25 ms frame on 2 cores (counted with a perf probe on LLVMCreateBuilderInContext: one
// per pass per frame before, none after). A value read at an index the compiler cannot fold keeps these
// branches out of its reach; on a GPU it is one more uniform load.
#ifndef UNIFORM_BRANCH_H
#define UNIFORM_BRANCH_H

// Zero in every dispatch of the passes that include this: they are flat (z = 1; their y holds the rows
// of a wide dispatch, shaders/dispatch.h).
uint unfoldable_zero() {
    return gl_NumWorkGroups.z - 1u;
}

#endif
