#include "cli.h"
#include "frame_source.h"
#include "fs_error.h"
#include "gl_context.h"
#include "method_params.h"
#include "options.h"
#include "render_output.h"
#include "shading.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* what --help says after the options */
static const char epilogue[] =
    "EXR output holds R G B A depth normal.X/Y/Z thickness coverage (+ own.R/G/B/A caustics\n"
    "for a method with its own appearance) and the provenance.\n";

int cmd_render(int argc, char **argv)
{
    const char *input = NULL, *out = NULL, *mname = "reference", *format = NULL;
    int w = 0, h = 0, frame = -1, timings = 0, quiet = 0, own_look = 0, rc;
    float radius = 0;
    fs_ctx_kind ctx_kind = fs_gl_context_default_kind();
    static fs_scene scene;
    const char *sets[FS_MAX_SETS], *exports[4];
    int nsets = 0, nexports = 0;
    const cli_opt opts[] = {
        CLI_STRING_OPT("--method", mname, "NAME", "method to run (fluidsurf methods lists them); default reference"),
        CLI_OPT_OUT(out, "OUT.png|OUT.exr", "the image: PNG, or EXR with the G-buffer and provenance"),
        CLI_OPT_SET(sets, nsets),
        CLI_OPT_SIZE(w, h, 1, 16384, "image", "the scene's, else 512"),
        CLI_OPT_RADIUS(radius, "the scene's, else 0.025"),
        CLI_STRING_OPT("--format", format, "FMT", "particle file format (default: from the extension)"),
        CLI_INT_OPT("--frame", frame, 0, 100000000, "N", "frame of a sequence scene (default: its first)"),
        CLI_OPT_GL(ctx_kind),
        CLI_FLAG_OPT("--timings", timings, "print per-stage times and the renderer they ran on"),
        CLI_LIST_OPT("--export", exports, nexports, 4, "FILE",
                     "write the method's intermediate surface too (repeatable;\n"
                     "surfels: .vdb density grid, .ply surfels; volume_raycast:\n"
                     ".vdb density volume); -o is then optional"),
        CLI_CHOICE_OPT("--appearance", own_look, "shared|own", NULL,
                       "shared (default): the harness's shading, the same for\n"
                       "every method; own: the method's own (surfels: reflection,\n"
                       "refraction and caustics as its paper renders them;\n"
                       "volume_raycast: its transfer function)"),
        CLI_OPT_QUIET(quiet),
        CLI_END,
    };
    const cli_command cmd = {"render", "SCENE.json|PARTICLES --method NAME -o OUT.png|OUT.exr [options]", opts,
                             {&input, NULL, 1, "more than one input ('%s' and '%s')"}, epilogue};
    if ((rc = cli_parse(&cmd, argc, argv)) != CLI_GO_ON) return rc;
    if (!input) return cli_usage("render", "no scene or particle file given");
    if (!out && !nexports) return cli_usage("render", "no output given (-o OUT.png|OUT.exr)");
    const fs_method *m = fs_method_find(mname);
    if (!m) return cli_usage("render", "unknown method '%s' (see 'fluidsurf methods')", mname);
    if (out && (rc = fs_check_render_path(out))) return cli_error(rc);
    if (nexports && !m->export_file) return cli_usage("render", "--export: method '%s' exports nothing", mname);
    for (int i = 0; i < nexports; i++)
        if (cli_same_file(input, exports[i])) return cli_usage("render", "%s: export would overwrite the input", exports[i]);
    if (own_look && !m->writes_own)
        return cli_usage("render", "--appearance own: method '%s' has no own appearance (only the shared shading)", mname);
    if (out && cli_same_file(input, out)) return cli_usage("render", "%s: output would overwrite the input", out);

    if ((rc = cli_scene_from_arg(&scene, input))) return cli_error(rc);
    if (format && strlen(format) < sizeof scene.format) strcpy(scene.format, format);
    for (int i = 0; i < nsets; i++)
        if ((rc = fs_scene_add_set(&scene, sets[i]))) return cli_error(rc);
    if (w) scene.camera.width = w;
    if (h) scene.camera.height = h;
    if ((long)scene.camera.width * scene.camera.height > 16384L * 16384L / 4)
        return cli_usage("render", "%dx%d pixels is too large", scene.camera.width, scene.camera.height);
    double params[FS_MAX_PARAMS];
    if ((rc = fs_method_params_resolve(m, &scene, params))) return cli_error(rc);

    int first, last;
    fs_scene_frames(&scene, &first, &last);
    if (frame >= 0) {
        if (scene.frame_first < 0 && !scene.synth.shape) return cli_usage("render", "--frame: the scene is not a sequence");
        if (scene.frame_first >= 0 && (frame < scene.frame_first || frame > scene.frame_last))
            return cli_usage("render", "--frame %d: the scene has frames %d..%d", frame, scene.frame_first, scene.frame_last);
        first = frame;
    }
    fs_particles p;
    fs_stages st = {0};
    double tl = fs_now_ms();
    if ((rc = fs_scene_load_frame(&scene, first, &p))) return cli_error(rc);
    fs_stages_add(&st, "load", fs_now_ms() - tl);
    if (radius > 0) scene.radius = radius;
    else if (!scene.path[0] && p.radius > 0) scene.radius = p.radius;
    int radius_note = !scene.path[0] && !(radius > 0) && !(p.radius > 0) && !quiet;
    fs_scene_frame_particles(&scene, &p);
    fs_method_setup setup = {fs_scene_field(&scene), params, &scene};

    fs_grid grid = {0};
    fs_gl_context ctx = {0};
    fs_gbuffer g = {0};
    void *self = NULL;
    float *rgba = NULL;
    double t0 = fs_now_ms();
    if ((rc = fs_grid_build(&grid, &p, setup.field.H))) goto done;
    fs_stages_add(&st, "grid", fs_now_ms() - t0);
    if (m->needs_gl && (rc = fs_gl_context_create(&ctx, ctx_kind, 16, 16))) goto done;
    rc = FS_ERR_RUNTIME;
    if (!(self = m->create(&setup))) goto done;
    t0 = fs_now_ms();
    if ((rc = m->upload(self, &p, &grid))) goto done;
    fs_stages_add(&st, "upload", fs_now_ms() - t0);
    for (int i = 0; i < nexports; i++)
        if ((rc = m->export_file(self, exports[i]))) goto done;
    if (!out) goto done;
    if ((rc = fs_gbuffer_alloc(&g, scene.camera.width, scene.camera.height, fs_method_wants_color(m, &p)))) goto done;
    if (m->writes_own && (rc = fs_gbuffer_alloc_own(&g))) goto done;
    if ((rc = m->render(self, &scene.camera, &g, &st))) goto done;
    rc = FS_ERR_RUNTIME;
    if (!(rgba = malloc((size_t)g.w * g.h * 4 * sizeof(float)))) { fs_fail(rc, "out of memory"); goto done; }
    t0 = fs_now_ms();
    if (own_look) memcpy(rgba, g.own, (size_t)g.w * g.h * 4 * sizeof(float));
    else fs_shade(&scene, &scene.camera, &g, fs_scene_floor(&scene, &p), rgba);
    fs_stages_add(&st, "shade", fs_now_ms() - t0);
    fs_provenance prov;
    fs_provenance_init(&prov, &scene, m->needs_gl ? ctx.renderer : NULL, m->needs_gl ? ctx.version : NULL);
    char pstr[600], fstr[32];
    fs_method_params_string(m, params, pstr, sizeof pstr);
    fs_provenance_set(&prov, "method", m->name);
    fs_provenance_set(&prov, "params", pstr);
    snprintf(fstr, sizeof fstr, "%d", first);
    fs_provenance_set(&prov, "frame", fstr);
    rc = fs_write_render(out, &g, rgba, &prov);
    /* after success only, so a failing run prints exactly one line */
    if (!rc && radius_note) fprintf(stderr, "fluidsurf: note: %s: used r = %g (set --radius)\n", input, scene.radius);
    if (!rc && timings) {
        printf("stage,ms,renderer\n");
        /* loading, grid building and shading always run in C on the CPU */
        for (int i = 0; i < st.n; i++) {
            int cpu = !m->needs_gl || !strcmp(st.name[i], "load") || !strcmp(st.name[i], "grid") ||
                      !strcmp(st.name[i], "shade");
            printf("%s,%.3f,%s\n", st.name[i], st.ms[i], cpu ? "CPU" : ctx.renderer);
        }
    }
done:
    if (rc) cli_error(rc);
    if (self) m->destroy(self);
    free(rgba);
    fs_gbuffer_free(&g);
    if (m->needs_gl) fs_gl_context_destroy(&ctx);
    fs_grid_free(&grid);
    fs_particles_free(&p);
    return rc;
}
