/*
 * Whether a signal is ignored, as the program was started.
 *
 * A program started by `nohup`, or by a shell or a batch system that
 * ignores a signal for it, inherits that signal ignored. The runtime's
 * own record of the Haskell handlers does not know of it (it says
 * "default" for a signal no Haskell code has handled), so
 * "AFrobRobotSim.Run.Signals" asks the system before it installs a
 * handler, and leaves an ignored signal ignored.
 *
 * POSIX only: the package builds it on every system but Windows.
 */
#include <signal.h>
#include <stddef.h>

int afrp_signal_ignored(int sig)
{
    struct sigaction old;
    if (sigaction(sig, NULL, &old) != 0)
        return 0;
    return old.sa_handler == SIG_IGN;
}
