#include "cli.h"
#include "method.h"
#include "options.h"
#include <stdio.h>
#include <string.h>

/* The AOVs m declares, as their EXR channels. */
static void print_aovs(const fs_method *m)
{
    if (!m->naovs) return;
    printf("  AOVs (EXR channels):");
    for (int k = 0; k < m->naovs; k++) {
        const fs_aov_def *d = &m->aovs[k];
        printf("%s %s%s%s", k ? "," : "", d->name, d->ncomp == 4 ? ".R/G/B/A" : "",
               d->needs_color ? " (when the particles carry colour)" : "");
    }
    printf("\n");
}

int cmd_methods(int argc, char **argv)
{
    const char *name = NULL;
    const cli_opt opts[] = {CLI_END};
    const cli_command cmd = {"methods",
                             "[NAME]",
                             opts,
                             {&name, NULL, 1, "more than one method ('%s' and '%s')"},
                             "Lists every method (or one) with its paper and parameters;\n"
                             "set a parameter with --set NAME.PARAM=VALUE in any command that renders.\n"};
    int rc = cli_parse(&cmd, argc, argv);
    if (rc != CLI_GO_ON) return rc;
    if (name && !fs_method_find(name)) return cli_unknown_method("methods", "methods", name);
    for (int i = 0; i < fs_method_count(); i++) {
        const fs_method *m = fs_method_at(i);
        if (name && strcmp(name, m->name)) continue;
        printf("%s — %s\n  paper: %s; runs on: %s\n", m->name, m->description, m->paper[0] ? m->paper : "(ours)",
               m->needs_gl ? "OpenGL 4.5" : "CPU");
        if (m->appearance) printf("  own appearance (--appearance own): %s\n", m->appearance);
        if (m->exports) printf("  exports (--export): %s\n", m->exports);
        print_aovs(m);
        for (int k = 0; k < m->nparams; k++) {
            const fs_param_def *p = &m->params[k];
            char def[64], range[96];
            fs_param_format(p, p->def, def, sizeof def);
            if (p->type == FS_PARAM_ENUM) snprintf(range, sizeof range, "%s", p->choices);
            else if (p->type == FS_PARAM_BOOL) snprintf(range, sizeof range, "on|off");
            else snprintf(range, sizeof range, "[%g, %g]", p->min, p->max);
            printf("    %-14s = %-8s %-16s %s\n", p->name, def, range, p->help);
        }
    }
    return 0;
}
