/* SIGINT, SIGTERM and SIGHUP during a run: the handler only records the signal; the run's hooks
 * (gd_run_env progress and should_stop) turn it into GD_ERR_INTERRUPTED, the run's directory
 * removes its stage, and the command exits 128 + the signal with one line. A second signal ends
 * the process at once, and the gnuplot drawing for it (what it staged is removed by the next run
 * into the directory). */
#include "cli.h"
#include "gnuplot.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static volatile sig_atomic_t g_caught = 0;

static void on_signal(int sig)
{
    if (g_caught) {
        static const char msg[] = "geardyn: second signal: stopping at once\n";
        ssize_t w = write(2, msg, sizeof msg - 1);
        (void)w;
        gd_gnuplot_end_running();
        _exit(128 + sig);
    }
    g_caught = sig;
}

void cli_signals_catch(void)
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
        struct sigaction sa, old;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_RESTART;
        sigaction(sigs[i], &sa, &old);
        if (old.sa_handler == SIG_IGN) /* started in the background or under nohup: leave it so */
            sigaction(sigs[i], &old, NULL);
    }
}

int cli_signal_caught(void) { return g_caught; }

const char *cli_signal_name(int sig)
{
    return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : sig == SIGHUP ? "SIGHUP" : "a signal";
}

int cli_should_stop(void *user)
{
    (void)user;
    return g_caught != 0;
}

int cli_interrupted(const char *dir)
{
    int sig = g_caught;
    /* a published result ends with its summary.json (src/output/stage.c) */
    char summary[4096];
    int had = snprintf(summary, sizeof summary, "%s/summary.json", dir) < (int)sizeof summary &&
              access(summary, F_OK) == 0;
    fprintf(stderr, "\ngeardyn: interrupted by %s: nothing published, %s %s\n", cli_signal_name(sig), dir,
            had ? "keeps its previous result" : "holds no result");
    return 128 + sig;
}
