/* fluidsurf report DIR: (re)writes DIR/report.html, the interactive comparison
 * page, from a finished study folder (report_html.h). */
#include "cli.h"
#include "fs_error.h"
#include "options.h"
#include "report_html.h"
#include <stdio.h>
#include <sys/stat.h>

static const char epilogue[] = "DIR is the output folder of 'fluidsurf compare' or 'merge' (which write the page\n"
                               "themselves): the page is rebuilt from DIR's metrics.csv, timings.csv, temporal.csv,\n"
                               "counters.csv, report.md and PNGs, so an older study or one copied elsewhere gets one.\n"
                               "Open DIR/report.html in a browser: it loads nothing from the network.\n"
                               "Keys: 1-9 or arrows pick the method, f flips to the reference, d toggles the split\n"
                               "line (drag it), l cycles the layers (shaded, normal error, depth error), o the\n"
                               "method's own appearance, wheel or +/- zooms (up to 16x), drag pans, r resets,\n"
                               "space plays a sequence, n or . steps a frame, ',' steps back.\n";

int cmd_report(int argc, char **argv)
{
    const char *dir = NULL;
    int rc;
    const cli_opt opts[] = {CLI_END};
    const cli_command cmd = {"report", "DIR", opts, {&dir, NULL, 1, "more than one folder ('%s' and '%s')"}, epilogue};
    if ((rc = cli_parse(&cmd, argc, argv)) != CLI_GO_ON) return rc;
    if (!dir) return cli_usage("report", "no study folder given");
    struct stat st;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) return cli_usage("report", "%s: not a folder", dir);
    if ((rc = fs_report_html_write(dir, 0))) return cli_error(rc);
    fs_note("wrote %s/report.html", dir);
    return 0;
}
