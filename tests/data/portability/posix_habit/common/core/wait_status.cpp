// A POSIX habit the MinGW check must catch: sys/wait.h with no Windows branch.
#include <sys/wait.h>

int exitCodeOf(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : -1; }
