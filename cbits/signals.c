/*
 * SIGTERM as "AFrobRobotSim.Run.Signals" handles it, in C: whether the
 * signal is ignored, and a watchdog for a runtime that cannot act.
 *
 * Whether a signal is ignored, as the program was started: a program
 * started by `nohup`, or by a shell or a batch system that ignores a
 * signal for it, inherits that signal ignored. The runtime's own record
 * of the Haskell handlers does not know of it (it says "default" for a
 * signal no Haskell code has handled), so the module asks the system
 * before it installs a handler, and leaves an ignored signal ignored.
 *
 * The watchdog: the runtime runs a Haskell handler on one of its own
 * threads, and stops the run by throwing to the run's thread. A
 * controller caught in a loop that never allocates keeps its capability
 * from the runtime (no collection can start, and with one capability no
 * handler can run), and the program would go on for ever, SIGTERM or
 * not. So, while a run may be stopped, the handler of SIGTERM installed
 * here wakes a thread of its own, made once, before it calls the
 * runtime's handler: it writes a byte into a pipe that the thread reads
 * (write is safe in a signal handler; a pipe, rather than a semaphore,
 * because unnamed semaphores do not exist on every POSIX system, macOS's
 * among them, where the watchdog would silently be missing). That thread
 * counts the grace down, and the Haskell side says when the runtime has
 * acted: each time one of its collections completes (which needs every
 * capability), from the signal's handler and, while a stop is on its way
 * to the run's thread, from a heartbeat every second
 * (`afrp_term_grace_begin`, `afrp_term_grace_renew`: a countdown begins
 * anew), and once no handler is at work any more (`afrp_term_grace_end`:
 * nothing to count until the next signal). If a countdown runs out, the
 * thread writes the message it was given to standard error and ends the
 * program by SIGTERM after all (exit status 143 in a shell), as it would
 * have ended without a handler. No signal other than SIGTERM is touched.
 *
 * One run watched at a time: `afrp_term_grace_arm` refuses while one
 * is, and a second run's handler (installed while the first is watched)
 * is wrapped again by `afrp_term_grace_rewrap`, so that the first stays
 * watched. POSIX only: the package builds it on every system but Windows.
 */
#if defined(__linux__)
#define _GNU_SOURCE   /* pipe2 */
#endif
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stddef.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

int afrp_signal_ignored(int sig)
{
    struct sigaction old;
    if (sigaction(sig, NULL, &old) != 0)
        return 0;
    return old.sa_handler == SIG_IGN;
}

/* The watchdog's state. `armed`: between arm and remove; `pending`: the
   runtime is expected to act (a SIGTERM has come, or a stop is on its
   way) and a countdown runs; `holders`: the Haskell handlers at work
   (each between a begin and its end; while any is, the runtime stays
   expected to act);
   `generation`: counts the arms, so that a countdown begun for one run
   never ends another. Read and written with the compiler's atomic
   builtins (the handler runs on any thread). The watchdog's thread is
   made at the first arm and lives as long as the program, asleep reading
   its pipe when there is nothing to watch (each byte written is one
   wake-up). */
static int armed = 0;
static int pending = 0;
static int generation = 0;
static int clears = 0;     /* counts the runtime's acts, so that a countdown ends at one */
static int holders = 0;
static int grace_seconds = 0;
static int wake_read = -1, wake_write = -1;   /* the pipe's ends */
static pthread_once_t started = PTHREAD_ONCE_INIT;
static int start_failed = 0;
static struct sigaction runtime_action;   /* the handler called after ours */
static char grace_message[2048];
static size_t grace_length = 0;

#define LOAD(x)     __atomic_load_n(&(x), __ATOMIC_SEQ_CST)
#define STORE(x, v) __atomic_store_n(&(x), (v), __ATOMIC_SEQ_CST)

/* The watchdog woken (once for each call). The write end does not block:
   should the pipe ever be full, the watchdog has wake-ups waiting anyway. */
static void wake(void)
{
    char byte = 0;
    ssize_t n;
    do
        n = write(wake_write, &byte, 1);
    while (n < 0 && errno == EINTR);
}

/* The next wake-up waited for; 0 when one came, -1 should the pipe fail
   (it never closes: both ends live as long as the program). */
static int wait_for_wake(void)
{
    char byte;
    ssize_t n;
    do
        n = read(wake_read, &byte, 1);
    while (n < 0 && errno == EINTR);
    return n == 1 ? 0 : -1;
}

static void on_term(int sig, siginfo_t *info, void *context)
{
    int saved = errno;
    if (LOAD(armed) && __atomic_exchange_n(&pending, 1, __ATOMIC_SEQ_CST) == 0)
        wake();
    errno = saved;
    runtime_action.sa_sigaction(sig, info, context);
}

static double now_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double) t.tv_sec + (double) t.tv_nsec * 1e-9;
}

static void end_by_sigterm(void)
{
    size_t done = 0;
    struct sigaction dfl;
    while (done < grace_length) {
        ssize_t n = write(2, grace_message + done, grace_length - done);
        if (n <= 0) break;
        done += (size_t) n;
    }
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(SIGTERM, &dfl, NULL);
    kill(getpid(), SIGTERM);
    /* (a thread that does not block SIGTERM takes it; should none, in a
       second the program ends as a shell would report it) */
    sleep(1);
    _exit(128 + SIGTERM);
}

static void *watchdog(void *unused)
{
    sigset_t all;
    (void) unused;
    /* (no signal is delivered to this thread: the runtime's go to its own) */
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, NULL);
    for (;;) {
        int gen, cleared;
        double deadline;
        struct timespec step = { 0, 50 * 1000 * 1000 };
        if (wait_for_wake() != 0)
            return NULL;   /* (no pipe: unreachable, as arm refuses without one) */
        gen = LOAD(generation);
        cleared = LOAD(clears);
        if (!LOAD(armed) || !LOAD(pending))
            continue;
        deadline = now_seconds() + (double) grace_seconds;
        while (LOAD(armed) && LOAD(pending) && LOAD(generation) == gen && LOAD(clears) == cleared
               && now_seconds() < deadline)
            nanosleep(&step, NULL);
        if (LOAD(armed) && LOAD(pending) && LOAD(generation) == gen && LOAD(clears) == cleared)
            end_by_sigterm();
        if (LOAD(pending))
            wake();   /* (still expected, after a renewal: a countdown of its own) */
    }
    return NULL;
}

static void start_watchdog(void)
{
    pthread_t thread;
    pthread_attr_t attr;
    int ends[2];
    int flags;
    /* (closed in the programs the run starts, ffmpeg's say, from the
       start where the system can: pipe2; the write end never blocks the
       signal handler) */
#if defined(__linux__)
    if (pipe2(ends, O_CLOEXEC) != 0) {
        start_failed = 1;
        return;
    }
#else
    if (pipe(ends) != 0) {
        start_failed = 1;
        return;
    }
    if (fcntl(ends[0], F_SETFD, FD_CLOEXEC) != 0 || fcntl(ends[1], F_SETFD, FD_CLOEXEC) != 0) {
        close(ends[0]);
        close(ends[1]);
        start_failed = 1;
        return;
    }
#endif
    flags = fcntl(ends[1], F_GETFL);
    if (flags < 0 || fcntl(ends[1], F_SETFL, flags | O_NONBLOCK) != 0) {
        close(ends[0]);
        close(ends[1]);
        start_failed = 1;
        return;
    }
    wake_read = ends[0];
    wake_write = ends[1];
    pthread_attr_init(&attr);
    pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
    if (pthread_create(&thread, &attr, watchdog, NULL) != 0) {
        close(wake_read);
        close(wake_write);
        wake_read = wake_write = -1;
        start_failed = 1;
    }
    pthread_attr_destroy(&attr);
}

/* Ours installed in front of the runtime's handler `current` (which it
   calls after waking the watchdog), with its mask and flags: 0 when
   installed. */
static int wrap(const struct sigaction *current)
{
    struct sigaction mine;
    runtime_action = *current;
    memset(&mine, 0, sizeof mine);
    mine.sa_sigaction = on_term;
    mine.sa_mask = current->sa_mask;
    mine.sa_flags = current->sa_flags & ~SA_RESETHAND;
    return sigaction(SIGTERM, &mine, NULL);
}

/* Put the watchdog in front of the SIGTERM handler installed now (the
   runtime's, which must be a function taking the signal's information),
   with the grace in seconds (> 0) and the message to write should it
   end the program. 0 when armed; -1 when nothing was changed (armed
   already, no such handler, or no thread for the watchdog). */
int afrp_term_grace_arm(int seconds, const char *message)
{
    struct sigaction current;
    size_t n = strlen(message);
    if (seconds <= 0 || LOAD(armed) || sigaction(SIGTERM, NULL, &current) != 0
        || !(current.sa_flags & SA_SIGINFO) || current.sa_sigaction == NULL
        || current.sa_sigaction == on_term)
        return -1;
    pthread_once(&started, start_watchdog);
    if (start_failed)
        return -1;
    if (n >= sizeof grace_message)
        n = sizeof grace_message - 1;
    memcpy(grace_message, message, n);
    grace_message[n] = '\0';
    grace_length = n;
    grace_seconds = seconds;
    STORE(pending, 0);
    __atomic_add_fetch(&generation, 1, __ATOMIC_SEQ_CST);
    STORE(armed, 1);
    if (wrap(&current) != 0) {
        STORE(armed, 0);
        return -1;
    }
    return 0;
}

/* The runtime has acted (a collection has completed), and is expected to
   act again: the running countdown ended, a new one begun. Nothing when
   not armed. */
void afrp_term_grace_renew(void)
{
    if (!LOAD(armed))
        return;
    __atomic_add_fetch(&clears, 1, __ATOMIC_SEQ_CST);
    if (__atomic_exchange_n(&pending, 1, __ATOMIC_SEQ_CST) == 0)
        wake();
}

/* A Haskell handler of SIGTERM at work, its collection completed: a
   renewal, and the runtime stays expected to act until the handler's
   end (so that another handler, ending first, does not end the watch of
   a stop still on its way). */
void afrp_term_grace_begin(void)
{
    __atomic_add_fetch(&holders, 1, __ATOMIC_SEQ_CST);
    afrp_term_grace_renew();
}

/* A handler's work done (its stop delivered, or none to deliver): when it
   was the last at work, the runtime has acted on every signal so far, and
   the watchdog waits for the next one. (Only the first signal's handler
   delivers a stop, and the others decide after it has begun, so the count
   reaches 0 only once its stop has been delivered.) */
void afrp_term_grace_end(void)
{
    if (__atomic_sub_fetch(&holders, 1, __ATOMIC_SEQ_CST) == 0) {
        __atomic_add_fetch(&clears, 1, __ATOMIC_SEQ_CST);
        STORE(pending, 0);
    }
}

/* After the runtime's handler of SIGTERM has been installed again (by
   another run's `installHandler`, or as it ends), while a watchdog is
   armed: ours put back in front of it. */
void afrp_term_grace_rewrap(void)
{
    struct sigaction current;
    if (!LOAD(armed) || sigaction(SIGTERM, NULL, &current) != 0
        || !(current.sa_flags & SA_SIGINFO) || current.sa_sigaction == NULL
        || current.sa_sigaction == on_term)
        return;
    wrap(&current);
}

/* SIGTERM's handler put back as it was when the watchdog was armed (unless
   something else has replaced ours since), then the watchdog disarmed;
   the caller then restores its own handler. */
void afrp_term_grace_remove(void)
{
    struct sigaction current;
    if (!LOAD(armed))
        return;
    if (sigaction(SIGTERM, NULL, &current) == 0 && (current.sa_flags & SA_SIGINFO)
        && current.sa_sigaction == on_term)
        sigaction(SIGTERM, &runtime_action, NULL);
    STORE(armed, 0);
    STORE(pending, 0);
    wake();
}
