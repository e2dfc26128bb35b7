/**
 * @file paper_tool.h
 * @brief Exits shared by the paper-reproduction programs (se23-montecarlo,
 *        se23-paper-table): both exit with status 2 on a usage or library
 *        error, 1 on a failed --check.
 */
#ifndef PAPER_TOOL_H
#define PAPER_TOOL_H

#include <stdio.h>
#include <stdlib.h>

#include "se23/types.h"

/** Prints "PROG: WHAT failed: STATUS" and exits with status 2. */
static inline void paper_die(const char *prog, const char *what, se23_status_t st)
{
    fprintf(stderr, "%s: %s failed: %s\n", prog, what, se23_status_str(st));
    exit(2);
}

/** Prints "usage: TEXT" and exits with status 2. */
static inline void paper_usage(const char *text)
{
    fprintf(stderr, "usage: %s\n", text);
    exit(2);
}

#endif /* PAPER_TOOL_H */
