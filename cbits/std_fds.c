/*
 * Standard descriptors closed when the program starts.
 *
 * A program started with standard output closed (`prog >&-`, some daemons
 * and cron setups) has no descriptor 1. The threaded GHC runtime then opens
 * its timer, and the I/O manager its event descriptors, and the first of
 * them takes the lowest free number: 1. The Handle `stdout` still writes to
 * descriptor 1, which is now the timer: it never becomes writable, and the
 * first write waits forever (the program hangs instead of failing).
 *
 * This constructor runs before `main`, so before the runtime starts: every
 * standard descriptor that is closed is opened on /dev/null, read-only.
 * Writing to descriptor 1 or 2 then fails with EBADF, as writing to a
 * closed descriptor does, and the program reports the failure and exits
 * non-zero; reading descriptor 0 gives end of file. Descriptors that are
 * open are left alone.
 *
 * POSIX only: the package builds it on every system but Windows, where
 * "AFrobRobotSim.Console" does without it.
 *
 * `afrp_std_fds_reopened` tells which were closed (bit k for descriptor k);
 * "AFrobRobotSim.Console" calls it, which also makes the linker keep this
 * file (and so its constructor) in every program that uses the console.
 */
#include <errno.h>
#include <fcntl.h>
#include <unistd.h>

static int reopened = 0;

/* (priority 101, the first a program may use: before other constructors
   that might open a file and take a free standard number) */
__attribute__((constructor(101)))
static void afrp_reopen_std_fds(void)
{
    int fd;
    for (fd = 0; fd <= 2; fd++) {
        if (fcntl(fd, F_GETFD) == -1 && errno == EBADF) {
            /* the lowest free number is fd itself: those below are open */
            int got = open("/dev/null", O_RDONLY);
            if (got == fd) {
                reopened |= 1 << fd;
            } else if (got >= 0) {
                /* (only if a lower one was closed and could not be opened) */
                if (dup2(got, fd) == fd) reopened |= 1 << fd;
                close(got);
            }
        }
    }
}

int afrp_std_fds_reopened(void)
{
    return reopened;
}
