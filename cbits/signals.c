/*
 * SIGTERM as "AFrobRobotSim.Run.Signals" handles it, in C: whether the
 * signal is ignored, and a grace period for a runtime that cannot act.
 *
 * Whether a signal is ignored, as the program was started: a program
 * started by `nohup`, or by a shell or a batch system that ignores a
 * signal for it, inherits that signal ignored. The runtime's own record
 * of the Haskell handlers does not know of it (it says "default" for a
 * signal no Haskell code has handled), so the module asks the system
 * before it installs a handler, and leaves an ignored signal ignored.
 *
 * The grace period: the runtime runs a Haskell handler on one of its own
 * threads, and stops the run by throwing to the run's thread. A
 * controller caught in a loop that never allocates keeps its capability
 * from the runtime, and then neither happens: the program would go on
 * for ever, SIGTERM or not. So, while a run may be stopped, a SIGTERM
 * also sets an alarm, before the runtime's own handler is called; the
 * run clears it once it is stopped and writing its outputs (or when the
 * signal is ignored because it already is). Should the alarm ring, the
 * runtime is stuck: the program writes the message it was given to
 * standard error and ends by SIGTERM after all (exit status 143 in a
 * shell), as it would have without a handler. Only async-signal-safe
 * calls are made in the handlers.
 *
 * POSIX only: the package builds it on every system but Windows.
 */
#include <signal.h>
#include <stddef.h>
#include <string.h>
#include <unistd.h>

int afrp_signal_ignored(int sig)
{
    struct sigaction old;
    if (sigaction(sig, NULL, &old) != 0)
        return 0;
    return old.sa_handler == SIG_IGN;
}

/* the handler of SIGTERM this one calls after setting the alarm (the
   runtime's), the grace in seconds, whether the alarm is set, and the
   message */
static struct sigaction grace_next;
static volatile sig_atomic_t grace_seconds = 0;
static volatile sig_atomic_t grace_set = 0;
static char grace_message[2048];
static size_t grace_length = 0;

static void grace_on_term(int sig, siginfo_t *info, void *context)
{
    if (grace_seconds > 0 && !grace_set) {
        grace_set = 1;
        alarm((unsigned) grace_seconds);
    }
    if (grace_next.sa_flags & SA_SIGINFO) {
        if (grace_next.sa_sigaction != NULL)
            grace_next.sa_sigaction(sig, info, context);
    } else if (grace_next.sa_handler != SIG_DFL && grace_next.sa_handler != SIG_IGN
               && grace_next.sa_handler != NULL) {
        grace_next.sa_handler(sig);
    }
}

static void grace_on_alarm(int sig)
{
    size_t done = 0;
    struct sigaction dfl;
    sigset_t term;
    (void) sig;
    while (done < grace_length) {
        ssize_t n = write(2, grace_message + done, grace_length - done);
        if (n <= 0) break;
        done += (size_t) n;
    }
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(SIGTERM, &dfl, NULL);
    sigemptyset(&term);
    sigaddset(&term, SIGTERM);
    sigprocmask(SIG_UNBLOCK, &term, NULL);
    raise(SIGTERM);
    _exit(128 + SIGTERM);
}

/* Put the grace period in front of the SIGTERM handler installed now (the
   runtime's): seconds > 0, and the message to write should it end. 0 on
   success, -1 if a handler could not be installed (nothing changed). */
int afrp_term_grace_arm(int seconds, const char *message)
{
    struct sigaction current, mine, alarm_action;
    size_t n = strlen(message);
    if (seconds <= 0 || sigaction(SIGTERM, NULL, &current) != 0)
        return -1;
    if (n >= sizeof grace_message)
        n = sizeof grace_message - 1;
    memcpy(grace_message, message, n);
    grace_message[n] = '\0';
    grace_length = n;
    memset(&alarm_action, 0, sizeof alarm_action);
    alarm_action.sa_handler = grace_on_alarm;
    sigemptyset(&alarm_action.sa_mask);
    if (sigaction(SIGALRM, &alarm_action, NULL) != 0)
        return -1;
    grace_next = current;
    grace_set = 0;
    grace_seconds = seconds;
    memset(&mine, 0, sizeof mine);
    mine.sa_sigaction = grace_on_term;
    mine.sa_mask = current.sa_mask;
    mine.sa_flags = (current.sa_flags | SA_SIGINFO) & ~SA_RESETHAND;
    if (sigaction(SIGTERM, &mine, NULL) != 0) {
        grace_seconds = 0;
        signal(SIGALRM, SIG_DFL);
        return -1;
    }
    return 0;
}

/* The run is stopped, or the signal ignored: the runtime is acting. */
void afrp_term_grace_clear(void)
{
    alarm(0);
    grace_set = 0;
}

/* No more grace: the alarm cleared and SIGTERM's handler put back as it
   was when the grace was armed (the caller then restores its own). */
void afrp_term_grace_remove(void)
{
    struct sigaction current;
    grace_seconds = 0;
    alarm(0);
    grace_set = 0;
    if (sigaction(SIGTERM, NULL, &current) == 0 && (current.sa_flags & SA_SIGINFO)
        && current.sa_sigaction == grace_on_term)
        sigaction(SIGTERM, &grace_next, NULL);
    signal(SIGALRM, SIG_DFL);
}
