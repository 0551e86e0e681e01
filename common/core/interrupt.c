/* The handler of interrupt.h: only async-signal-safe calls (unlink, write, _exit). */
#include "interrupt.h"
#include "output_file.h"
#include "progress.h"

#include <signal.h>
#include <string.h>
#include <unistd.h>

static void say(const char *s) { (void)!write(STDERR_FILENO, s, strlen(s)); }

static void on_signal(int sig)
{
    fs_output_abandon_all();
    char done[96];
    fs_progress_summary(done, sizeof done);
    /* a progress bar may be on the line */
    say(isatty(STDERR_FILENO) ? "\r\033[K" : "");
    say(sig == SIGINT ? "fluidsurf: interrupted (SIGINT)" : "fluidsurf: terminated (SIGTERM)");
    if (done[0]) {
        say(" after ");
        say(done);
    }
    say("; finished outputs kept, temporary files removed\n");
    _exit(128 + sig);
}

void fs_interrupt_install(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaddset(&sa.sa_mask, SIGINT);
    sigaddset(&sa.sa_mask, SIGTERM);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}
