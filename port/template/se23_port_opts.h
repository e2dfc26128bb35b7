/*
 * Options of a new port: copy port/template to port/<name> and fill in.
 * Build the library with -Iport/<name>
 * -DSE23_CFG_OPTS_FILE='"se23_port_opts.h"'. This file is included by
 * include/se23/config.h before its defaults, so it may also set the library
 * options (SE23_CFG_DOUBLE, SE23_CFG_ARG_CHECKS, ...; see config.h).
 *
 * Math overrides: each takes and returns the build's precision
 * (float when SE23_CFG_DOUBLE is 0). Leave undefined to use libm.
 */
#ifndef SE23_PORT_OPTS_H
#define SE23_PORT_OPTS_H

/* #define SE23_CFG_DOUBLE 0 */
/* #define SE23_SQRT my_sqrtf */
/* #define SE23_ATAN2 my_atan2f */
/* #define SE23_FMOD my_fmodf */
/* #define SE23_FABS my_fabsf */

#endif /* SE23_PORT_OPTS_H */
