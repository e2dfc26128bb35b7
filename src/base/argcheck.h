/**
 * @file argcheck.h
 * @brief Internal: argument checks of public functions, compiled in only
 *        with SE23_CFG_ARG_CHECKS (config.h).
 */
#ifndef SE23_ARGCHECK_H
#define SE23_ARGCHECK_H

#include <stddef.h>

#include "se23/types.h"

#if SE23_CFG_ARG_CHECKS
/** Returns SE23_ERR_NULL from the calling function if p is NULL. */
#define SE23_CHECK_NOT_NULL(p)                                                 \
    do {                                                                       \
        if ((p) == NULL) {                                                     \
            return SE23_ERR_NULL;                                              \
        }                                                                      \
    } while (0)
#else
#define SE23_CHECK_NOT_NULL(p) ((void)0)
#endif

#endif /* SE23_ARGCHECK_H */
