/*
 * Hand-written adapters (tv_call_<fn>) for the TV_CUSTOM rows of tv_list.h:
 * routines whose arguments are not all structs of reals (scalars, enums,
 * several outputs). Same contract as the generic adapters in tv_runner.c:
 * unpack the input row, pre-fill outputs with TV_SENTINEL, call, pack the
 * outputs, return the status.
 */
#include <string.h>

#include "tv.h"
