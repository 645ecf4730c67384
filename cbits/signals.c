/*
 * SIGTERM and SIGINT (Ctrl-C) as "AFrobRobotSim.Run.Signals" handles
 * them, in C: whether a signal is ignored, and a watchdog for a runtime
 * that cannot act.
 *
 * Whether a signal is ignored, as the program was started: a program
 * started by `nohup`, or by a shell or a batch system that ignores a
 * signal for it, inherits that signal ignored. The runtime's own record
 * of the Haskell handlers does not know of it (it says "default" for a
 * signal no Haskell code has handled), so the module asks the system
 * before it installs a handler, and leaves an ignored signal ignored.
 *
 * The watchdog: the runtime runs a Haskell handler on one of its own
 * threads, which stops the run by throwing to a thread (SIGTERM's, the
 * module's, to the run's thread; SIGINT's, the runtime's own, to the main
 * thread). A controller caught in a loop that never allocates keeps its
 * capability from the runtime (no collection can start, and with one
 * capability no handler can run), and the program would go on for ever,
 * signal or not. So, while a run may be stopped, the handler installed
 * here in front of the runtime's wakes a thread of its own, one for each
 * signal, made once, before it calls the runtime's handler: it writes a
 * byte into a pipe that the thread reads (write is safe in a signal
 * handler; a pipe, rather than a semaphore, because unnamed semaphores
 * do not exist on every POSIX system, macOS's among them, where the
 * watchdog would silently be missing). That thread counts the grace
 * down, and the Haskell side says when the runtime has acted: each time
 * one of its collections completes (which needs every capability), from
 * the signal's Haskell handler and, while a stop is on its way to its
 * thread, from a heartbeat every second (`afrp_grace_begin`,
 * `afrp_grace_renew`: a countdown begins anew), and once no handler is
 * at work any more (`afrp_grace_end`: nothing to count until the next
 * signal). If a countdown runs out, the thread writes the message it was
 * given to standard error and ends the program by the signal after all
 * (exit status 143 for SIGTERM, 130 for SIGINT, in a shell), as it would
 * have ended without a handler. No other signal is touched.
 *
 * The runtime's SIGINT handler is called once (SA_RESETHAND: the system
 * puts the default action back as it calls it, so that a second Ctrl-C
 * ends the program at once). Ours in front of it keeps that rule itself:
 * it calls the runtime's handler for the first SIGINT only, and at a
 * second writes a message saying that the program ends at once, then
 * ends it by the default action, as it would have ended; once the run is
 * over, the default action is left where the runtime's rule would have
 * left it.
 *
 * One run watched at a time for each signal: `afrp_grace_arm` refuses
 * while one is, and a second run's handler (installed while the first is
 * watched) is wrapped again by `afrp_grace_rewrap`, so that the first
 * stays watched. POSIX only: the package builds it on every system but
 * Windows.
 */
#if defined(__linux__)
#define _GNU_SOURCE   /* pipe2 */
#endif
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
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

/* A watchdog's state, one for each signal watched. `armed`: between arm
   and remove; `pending`: the runtime is expected to act (the signal has
   come, or a stop is on its way) and a countdown runs; `holders`: the
   Haskell handlers at work (each between a begin and its end; while any
   is, the runtime stays expected to act); `generation`: counts the arms,
   so that a countdown begun for one run never ends another; `clears`:
   counts the runtime's acts, so that a countdown ends at one. Read and
   written with the compiler's atomic builtins (the handler runs on any
   thread). A watchdog's thread is made at its first arm and lives as long
   as the program, asleep reading its pipe when there is nothing to watch
   (each byte written is one wake-up). `once`: the runtime's handler is
   called once (SA_RESETHAND: the system puts the default action back as
   it calls it; the runtime's SIGINT, so that a second Ctrl-C ends the
   program at once), and ours in front of it calls it once too, `fired`
   saying it has: ours stays, and a second signal, rather than meeting
   the default action silently, writes `again` (its message) to standard
   error and then ends the program by the default action. */
struct watch {
    int sig;
    int once;
    int fired;
    int armed;
    int pending;
    int generation;
    int clears;
    int holders;
    int grace_seconds;
    int wake_read, wake_write;   /* the pipe's ends */
    int start_failed;
    struct sigaction runtime_action;   /* the handler called after ours */
    char message[2048];
    size_t length;
    char again[2048];
    size_t again_length;
};

static struct watch term_watch = { SIGTERM, 0, 0, 0, 0, 0, 0, 0, 0, -1, -1, 0 };
static struct watch int_watch  = { SIGINT,  0, 0, 0, 0, 0, 0, 0, 0, -1, -1, 0 };
static pthread_once_t term_started = PTHREAD_ONCE_INIT;
static pthread_once_t int_started = PTHREAD_ONCE_INIT;

#define LOAD(x)     __atomic_load_n(&(x), __ATOMIC_SEQ_CST)
#define STORE(x, v) __atomic_store_n(&(x), (v), __ATOMIC_SEQ_CST)

/* The watch of a signal: NULL for one not watched here. */
static struct watch *watch_of(int sig)
{
    return sig == SIGTERM ? &term_watch : sig == SIGINT ? &int_watch : NULL;
}

/* The watchdog woken (once for each call). The write end does not block:
   should the pipe ever be full, the watchdog has wake-ups waiting anyway. */
static void wake(struct watch *w)
{
    char byte = 0;
    ssize_t n;
    do
        n = write(w->wake_write, &byte, 1);
    while (n < 0 && errno == EINTR);
}

/* The next wake-up waited for; 0 when one came, -1 should the pipe fail
   (it never closes: both ends live as long as the program). */
static int wait_for_wake(struct watch *w)
{
    char byte;
    ssize_t n;
    do
        n = read(w->wake_read, &byte, 1);
    while (n < 0 && errno == EINTR);
    return n == 1 ? 0 : -1;
}

/* A message written to standard error, as far as it can be without
   waiting more than `wait_ms` milliseconds for it to take each part (a
   pipe nobody reads must not keep the program from ending: what it
   cannot take is not written). poll and write are safe in a signal
   handler. */
static void say(const char *text, size_t length, int wait_ms)
{
    size_t done = 0;
    while (done < length) {
        struct pollfd p = { 2, POLLOUT, 0 };
        ssize_t n;
        if (poll(&p, 1, wait_ms) != 1 || !(p.revents & POLLOUT))
            break;
        n = write(2, text + done, length - done);
        if (n <= 0) break;
        done += (size_t) n;
    }
}

/* The program ended by `sig`'s default action, after the message (said
   as `say` does): the default action put back first, so that the same
   signal sent again meanwhile ends the program at once; then the signal
   sent again, and unblocked in this thread (blocked in its handler, or in
   the watchdog's thread), so that it is taken here if no other thread
   takes it first (pthread_sigmask is safe in a signal handler); should
   it somehow not be taken within a second, the program ends as a shell
   would report it. */
static _Noreturn void end_by_default(int sig, const char *text, size_t length, int wait_ms)
{
    struct sigaction dfl;
    sigset_t just;
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(sig, &dfl, NULL);
    say(text, length, wait_ms);
    kill(getpid(), sig);
    sigemptyset(&just);
    sigaddset(&just, sig);
    pthread_sigmask(SIG_UNBLOCK, &just, NULL);
    sleep(1);
    _exit(128 + sig);
}

static void on_signal(int sig, siginfo_t *info, void *context)
{
    int saved = errno;
    struct watch *w = watch_of(sig);
    if (w == NULL)
        return;   /* (unreachable: installed for watched signals only) */
    if (LOAD(w->once) && __atomic_exchange_n(&w->fired, 1, __ATOMIC_SEQ_CST) != 0) {
        /* (the second: what the default action would have done, said if
           standard error takes it at once) */
        end_by_default(sig, w->again, w->again_length, 0);
    }
    if (LOAD(w->armed) && __atomic_exchange_n(&w->pending, 1, __ATOMIC_SEQ_CST) == 0)
        wake(w);
    errno = saved;
    w->runtime_action.sa_sigaction(sig, info, context);
    errno = saved;
}

static double now_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double) t.tv_sec + (double) t.tv_nsec * 1e-9;
}

/* The message written, and the program ended by the watched signal after
   all, as it would have ended without a handler. */
static void end_by_signal(struct watch *w)
{
    end_by_default(w->sig, w->message, w->length, 1000);
}

static void *watchdog(void *arg)
{
    struct watch *w = arg;
    sigset_t all;
    /* (no signal is delivered to this thread: the runtime's go to its own) */
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, NULL);
    for (;;) {
        int gen, cleared;
        double deadline;
        struct timespec step = { 0, 50 * 1000 * 1000 };
        if (wait_for_wake(w) != 0)
            return NULL;   /* (no pipe: unreachable, as arm refuses without one) */
        gen = LOAD(w->generation);
        cleared = LOAD(w->clears);
        if (!LOAD(w->armed) || !LOAD(w->pending))
            continue;
        deadline = now_seconds() + (double) w->grace_seconds;
        while (LOAD(w->armed) && LOAD(w->pending) && LOAD(w->generation) == gen
               && LOAD(w->clears) == cleared && now_seconds() < deadline)
            nanosleep(&step, NULL);
        if (LOAD(w->armed) && LOAD(w->pending) && LOAD(w->generation) == gen && LOAD(w->clears) == cleared)
            end_by_signal(w);
        if (LOAD(w->pending))
            wake(w);   /* (still expected, after a renewal: a countdown of its own) */
    }
    return NULL;
}

static void start_watchdog(struct watch *w)
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
        w->start_failed = 1;
        return;
    }
#else
    if (pipe(ends) != 0) {
        w->start_failed = 1;
        return;
    }
    if (fcntl(ends[0], F_SETFD, FD_CLOEXEC) != 0 || fcntl(ends[1], F_SETFD, FD_CLOEXEC) != 0) {
        close(ends[0]);
        close(ends[1]);
        w->start_failed = 1;
        return;
    }
#endif
    flags = fcntl(ends[1], F_GETFL);
    if (flags < 0 || fcntl(ends[1], F_SETFL, flags | O_NONBLOCK) != 0) {
        close(ends[0]);
        close(ends[1]);
        w->start_failed = 1;
        return;
    }
    w->wake_read = ends[0];
    w->wake_write = ends[1];
    pthread_attr_init(&attr);
    pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
    if (pthread_create(&thread, &attr, watchdog, w) != 0) {
        close(w->wake_read);
        close(w->wake_write);
        w->wake_read = w->wake_write = -1;
        w->start_failed = 1;
    }
    pthread_attr_destroy(&attr);
}

static void start_term_watchdog(void) { start_watchdog(&term_watch); }
static void start_int_watchdog(void)  { start_watchdog(&int_watch); }

/* Ours installed in front of the runtime's handler `current` (which it
   calls after waking the watchdog), with its mask and flags less
   SA_RESETHAND (for a SIGINT handler that has it, ours calls it once
   itself: `once`): 0 when installed. */
static int wrap(struct watch *w, const struct sigaction *current)
{
    struct sigaction mine;
    w->runtime_action = *current;
    memset(&mine, 0, sizeof mine);
    mine.sa_sigaction = on_signal;
    mine.sa_mask = current->sa_mask;
    mine.sa_flags = current->sa_flags & ~SA_RESETHAND;
    STORE(w->fired, 0);
    STORE(w->once, w->sig == SIGINT && (current->sa_flags & SA_RESETHAND) != 0);
    return sigaction(w->sig, &mine, NULL);
}

/* Whether `current` is a handler ours can be put in front of: a function
   taking the signal's information (the runtime's), not ours already. */
static int wrappable(const struct sigaction *current)
{
    return (current->sa_flags & SA_SIGINFO) && current->sa_sigaction != NULL
           && current->sa_sigaction != on_signal;
}

/* A message kept in `into` (of `size` bytes, cut short to fit), its
   length in `length`. */
static void keep(char *into, size_t size, size_t *length, const char *message)
{
    size_t n = strlen(message);
    if (n >= size)
        n = size - 1;
    memcpy(into, message, n);
    into[n] = '\0';
    *length = n;
}

/* Put the watchdog of `sig` (SIGTERM or SIGINT) in front of its handler
   installed now (the runtime's, which must be a function taking the
   signal's information), with the grace in seconds (> 0), the message to
   write should it end the program, and the one to write should a second
   signal come to a handler called once (`once`). 0 when armed; -1 when
   nothing was changed (another signal, armed already, no such handler,
   or no thread for the watchdog). */
int afrp_grace_arm(int sig, int seconds, const char *message, const char *again)
{
    struct sigaction current;
    struct watch *w = watch_of(sig);
    if (w == NULL || seconds <= 0 || LOAD(w->armed) || sigaction(sig, NULL, &current) != 0
        || !wrappable(&current))
        return -1;
    /* (Ctrl-C: the runtime's own handler alone, called once; a program's
       own, installed with installHandler, stays after each signal and is
       left unwatched, as it was) */
    if (sig == SIGINT && !(current.sa_flags & SA_RESETHAND))
        return -1;
    pthread_once(sig == SIGTERM ? &term_started : &int_started,
                 sig == SIGTERM ? start_term_watchdog : start_int_watchdog);
    if (w->start_failed)
        return -1;
    keep(w->message, sizeof w->message, &w->length, message);
    keep(w->again, sizeof w->again, &w->again_length, again);
    w->grace_seconds = seconds;
    STORE(w->pending, 0);
    __atomic_add_fetch(&w->generation, 1, __ATOMIC_SEQ_CST);
    STORE(w->armed, 1);
    if (wrap(w, &current) != 0) {
        STORE(w->armed, 0);
        return -1;
    }
    return 0;
}

/* The runtime has acted (a collection has completed), and is expected to
   act again: the running countdown ended, a new one begun. Nothing when
   not armed. */
void afrp_grace_renew(int sig)
{
    struct watch *w = watch_of(sig);
    if (w == NULL || !LOAD(w->armed))
        return;
    __atomic_add_fetch(&w->clears, 1, __ATOMIC_SEQ_CST);
    if (__atomic_exchange_n(&w->pending, 1, __ATOMIC_SEQ_CST) == 0)
        wake(w);
}

/* A Haskell handler of the signal at work, its collection completed: a
   renewal, and the runtime stays expected to act until the handler's
   end (so that another handler, ending first, does not end the watch of
   a stop still on its way). */
void afrp_grace_begin(int sig)
{
    struct watch *w = watch_of(sig);
    if (w == NULL)
        return;
    __atomic_add_fetch(&w->holders, 1, __ATOMIC_SEQ_CST);
    afrp_grace_renew(sig);
}

/* A handler's work done (its stop delivered, or none to deliver): when it
   was the last at work, the runtime has acted on every signal so far, and
   the watchdog waits for the next one. (Only the first signal's handler
   delivers a stop, and the others decide after it has begun, so the count
   reaches 0 only once its stop has been delivered.) */
void afrp_grace_end(int sig)
{
    struct watch *w = watch_of(sig);
    if (w == NULL)
        return;
    if (__atomic_sub_fetch(&w->holders, 1, __ATOMIC_SEQ_CST) == 0) {
        __atomic_add_fetch(&w->clears, 1, __ATOMIC_SEQ_CST);
        STORE(w->pending, 0);
    }
}

/* After the runtime's handler of the signal has been installed again (by
   another run's `installHandler`, or as it ends), while its watchdog is
   armed: ours put back in front of it. */
void afrp_grace_rewrap(int sig)
{
    struct sigaction current;
    struct watch *w = watch_of(sig);
    if (w == NULL || !LOAD(w->armed) || sigaction(sig, NULL, &current) != 0 || !wrappable(&current))
        return;
    wrap(w, &current);
}

/* The signal's handler put back as it was when the watchdog was armed,
   or, when it was to be called once and has been, the default action, as
   it would have left it (unless something else has replaced ours since);
   then the watchdog disarmed; the caller then restores its own
   handler. */
void afrp_grace_remove(int sig)
{
    struct sigaction current;
    struct watch *w = watch_of(sig);
    if (w == NULL || !LOAD(w->armed))
        return;
    if (sigaction(sig, NULL, &current) == 0 && (current.sa_flags & SA_SIGINFO)
        && current.sa_sigaction == on_signal) {
        if (LOAD(w->once) && LOAD(w->fired)) {
            struct sigaction dfl;
            memset(&dfl, 0, sizeof dfl);
            dfl.sa_handler = SIG_DFL;
            sigemptyset(&dfl.sa_mask);
            sigaction(sig, &dfl, NULL);
        } else
            sigaction(sig, &w->runtime_action, NULL);
    }
    STORE(w->armed, 0);
    STORE(w->pending, 0);
    wake(w);
}
