/* GL limits: the table of needs and the check (gl_limits.h). Each need is the
 * largest use the shaders and the GL code make (derived in docs/DESIGN.md, "GL
 * limits"); the check runs once per context, so a driver below one fails with one
 * line before a method compiles a program it could not link. */
#include "gl_limits.h"
#include "fs_error.h"
#include "gl.h"

/* {pname, index, name, need, what}; index -1: a scalar (glGetInteger64v), 0..2: an
 * indexed compute limit (glGetIntegeri_v) or GL_MAX_VIEWPORT_DIMS's component. */
static const fs_gl_limit table[] = {
    {GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, -1, "GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS", 20,
     "the neighbour grid's storage blocks at bindings 8-19, shaders/common/grid.glsl"},
    {GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS, -1, "GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS", 12,
     "raycast_pca's normal pass: 11 neighbour-grid blocks and the work counters' block"},
    {GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS, -1, "GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS", 1,
     "sprite, splat, surfel and cube-face vertex shaders read their points from a storage block"},
    {GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS, -1, "GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS", 1,
     "the work counters: fragment shaders add to the counter block"},
    {GL_MAX_COMBINED_SHADER_STORAGE_BLOCKS, -1, "GL_MAX_COMBINED_SHADER_STORAGE_BLOCKS", 12,
     "raycast_pca's normal pass: 11 neighbour-grid blocks and the work counters' block"},
    {GL_MAX_SHADER_STORAGE_BLOCK_SIZE, -1, "GL_MAX_SHADER_STORAGE_BLOCK_SIZE", 134217728,
     "particle chunks and the GPU simulator's buffers: 128 MiB blocks, the GL 4.5 minimum"},
    {GL_MAX_COMBINED_SHADER_OUTPUT_RESOURCES, -1, "GL_MAX_COMBINED_SHADER_OUTPUT_RESOURCES", 16,
     "raycast_pca's normal pass: 12 storage blocks and 4 images"},
    {GL_MAX_IMAGE_UNITS, -1, "GL_MAX_IMAGE_UNITS", 6,
     "image bindings 0-5: surfels' normalize pass, volume_raycast's march"},
    {GL_MAX_COMPUTE_IMAGE_UNIFORMS, -1, "GL_MAX_COMPUTE_IMAGE_UNIFORMS", 6,
     "surfels' normalize pass and volume_raycast's march: 6 images each"},
    {GL_MAX_COMBINED_IMAGE_UNIFORMS, -1, "GL_MAX_COMBINED_IMAGE_UNIFORMS", 6,
     "surfels' normalize pass and volume_raycast's march: 6 images each"},
    {GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, -1, "GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS", 4,
     "surfels bind textures to units 1-3"},
    {GL_MAX_TEXTURE_IMAGE_UNITS, -1, "GL_MAX_TEXTURE_IMAGE_UNITS", 2,
     "surfels' fragment shader samples the caustic maps and the object slices"},
    {GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS, -1, "GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS", 2,
     "surfels' normalize pass samples the caustic maps and the object slices"},
    {GL_MAX_COMPUTE_WORK_GROUP_SIZE, 0, "GL_MAX_COMPUTE_WORK_GROUP_SIZE[x]", 128,
     "the GPU simulator's particle passes: local_size_x = 128"},
    {GL_MAX_COMPUTE_WORK_GROUP_SIZE, 1, "GL_MAX_COMPUTE_WORK_GROUP_SIZE[y]", 8, "image passes: 8 x 8 pixels"},
    {GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, -1, "GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS", 128,
     "the GPU simulator's particle passes: 128 x 1"},
    {GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, "GL_MAX_COMPUTE_WORK_GROUP_COUNT[x]", 65535,
     "one group per 128 particles (simulator), 64 (anisotropy) or 8 pixel columns"},
    {GL_MAX_COMPUTE_WORK_GROUP_COUNT, 1, "GL_MAX_COMPUTE_WORK_GROUP_COUNT[y]", 2048,
     "image passes: one group per 8 rows of a 16384-pixel image"},
    {GL_MAX_GEOMETRY_OUTPUT_VERTICES, -1, "GL_MAX_GEOMETRY_OUTPUT_VERTICES", 4,
     "volume_raycast's layered splat: 4 per grid layer (32 for its 8 layers per invocation)"},
    {GL_MAX_GEOMETRY_OUTPUT_COMPONENTS, -1, "GL_MAX_GEOMETRY_OUTPUT_COMPONENTS", 8,
     "volume_raycast's layered splat: gl_Position, gl_Layer and a vec3 per vertex"},
    {GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS, -1, "GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS", 32,
     "volume_raycast's layered splat: 4 vertices of 8 components per layer (256 for 8 layers)"},
    {GL_MAX_GEOMETRY_SHADER_INVOCATIONS, -1, "GL_MAX_GEOMETRY_SHADER_INVOCATIONS", 1,
     "volume_raycast's layered splat (up to 32 invocations when the driver has them)"},
    {GL_MAX_FRAMEBUFFER_LAYERS, -1, "GL_MAX_FRAMEBUFFER_LAYERS", 1024,
     "volume_raycast's layered splat: one layer per grid plane, grid_res up to 1024"},
    {GL_MAX_3D_TEXTURE_SIZE, -1, "GL_MAX_3D_TEXTURE_SIZE", 1024, "density grids: grid_res up to 1024 points"},
    {GL_MAX_TEXTURE_SIZE, -1, "GL_MAX_TEXTURE_SIZE", 16384, "G-buffer textures: images up to 16384 pixels a side"},
    {GL_MAX_RENDERBUFFER_SIZE, -1, "GL_MAX_RENDERBUFFER_SIZE", 16384,
     "the G-buffer's depth buffer: images up to 16384 pixels a side"},
    {GL_MAX_VIEWPORT_DIMS, 0, "GL_MAX_VIEWPORT_DIMS[0]", 16384, "images up to 16384 pixels a side"},
    {GL_MAX_VIEWPORT_DIMS, 1, "GL_MAX_VIEWPORT_DIMS[1]", 16384, "images up to 16384 pixels a side"},
    {GL_MAX_ARRAY_TEXTURE_LAYERS, -1, "GL_MAX_ARRAY_TEXTURE_LAYERS", 16,
     "surfels' caustic maps: up to 16 sample planes"},
    {GL_MAX_COLOR_ATTACHMENTS, -1, "GL_MAX_COLOR_ATTACHMENTS", 3,
     "the G-buffer's surface pass and surfels' blending pass: 3 colour targets"},
    {GL_MAX_DRAW_BUFFERS, -1, "GL_MAX_DRAW_BUFFERS", 3,
     "the G-buffer's surface pass and surfels' blending pass: 3 colour targets"},
    {GL_MAX_VERTEX_ATTRIBS, -1, "GL_MAX_VERTEX_ATTRIBS", 2, "mesh: position and normal attributes"},
    {GL_MAX_VERTEX_OUTPUT_COMPONENTS, -1, "GL_MAX_VERTEX_OUTPUT_COMPONENTS", 16,
     "surfels' caustic vertex shader: 16 components besides gl_Position"},
    {GL_MAX_FRAGMENT_INPUT_COMPONENTS, -1, "GL_MAX_FRAGMENT_INPUT_COMPONENTS", 16,
     "surfels' caustic fragment shader: 16 components"},
    {GL_MAX_VERTEX_UNIFORM_COMPONENTS, -1, "GL_MAX_VERTEX_UNIFORM_COMPONENTS", 44,
     "surfels' vertex shader (every uniform rounded up to whole vec4s)"},
    {GL_MAX_GEOMETRY_UNIFORM_COMPONENTS, -1, "GL_MAX_GEOMETRY_UNIFORM_COMPONENTS", 20,
     "the layered splat's geometry shader (every uniform rounded up to whole vec4s)"},
    {GL_MAX_FRAGMENT_UNIFORM_COMPONENTS, -1, "GL_MAX_FRAGMENT_UNIFORM_COMPONENTS", 168,
     "surfels' fragment shader (every uniform rounded up to whole vec4s)"},
    {GL_MAX_COMPUTE_UNIFORM_COMPONENTS, -1, "GL_MAX_COMPUTE_UNIFORM_COMPONENTS", 120,
     "surfels' normalize pass (every uniform rounded up to whole vec4s)"},
    {GL_MAX_UNIFORM_LOCATIONS, -1, "GL_MAX_UNIFORM_LOCATIONS", 33, "surfels' blending program: 33 locations"},
};

#define NLIMITS ((int)(sizeof table / sizeof *table))

const fs_gl_limit *fs_gl_limits(int *n)
{
    *n = NLIMITS;
    return table;
}

int fs_gl_limits_check(const long long *have, const char *renderer)
{
    const char *r = renderer && *renderer ? renderer : "this renderer";
    for (int i = 0; i < NLIMITS; i++) {
        const fs_gl_limit *l = &table[i];
        if (have[i] < 0) /* the query failed: a driver that does not know the limit */
            return fs_fail(FS_ERR_RUNTIME, "OpenGL: %s is not reported on %s; fluidsurf needs %lld (%s)", l->name, r,
                           l->need, l->what);
        if (have[i] < l->need)
            return fs_fail(FS_ERR_RUNTIME, "OpenGL: %s is %lld on %s; fluidsurf needs %lld (%s)", l->name, have[i], r,
                           l->need, l->what);
    }
    return FS_OK;
}

/* One limit of the current context; -1 when the driver answers nothing (an error). */
static long long query(const fs_gl_limit *l)
{
    GLint64 v64 = -1;
    GLint v[2] = {-1, -1};
    if (l->pname == GL_MAX_VIEWPORT_DIMS) {
        glGetIntegerv(l->pname, v); /* two values: width, height */
        v64 = v[l->index];
    } else if (l->index >= 0) {
        glGetIntegeri_v(l->pname, (GLuint)l->index, v);
        v64 = v[0];
    } else {
        glGetInteger64v(l->pname, &v64);
    }
    return glGetError() == GL_NO_ERROR ? (long long)v64 : -1;
}

void fs_gl_limits_query(long long *have)
{
    for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; i++) {} /* a stale error would read as a failed query */
    for (int i = 0; i < NLIMITS; i++) have[i] = query(&table[i]);
}

int fs_gl_limits_check_current(const char *renderer)
{
    long long have[NLIMITS];
    fs_gl_limits_query(have);
    return fs_gl_limits_check(have, renderer);
}
