fs_add_test(test_gl fs_gl test_gl.c)
# The EGL device choice and the software-renderer list, as pure functions (no GPU needed).
fs_add_test(test_gl_device fs_gl test_gl_device.c)
fs_add_test(test_spheres fs_test_methods test_spheres.c golden.c)
# The GL limits (docs/DESIGN.md, "GL limits"): each refused one below its need with one
# line, and the build's own context (OSMesa; EGL in the lean build) meets every need.
fs_add_test(test_gl_limits fs_gl test_gl_limits.c)
# The compute splatter against the raster on the demo and DualSPHysics frames (issue 47).
fs_add_test(test_splat_compute fs_test_methods test_splat_compute.c test_render.c)
# The read back through pixel pack buffers against the old synchronous path
# (FLUIDSURF_READBACK=sync): every GL method's EXR equal bit for bit, two sizes.
fs_add_test(test_readback fs_test_methods test_readback.c test_render.c)
