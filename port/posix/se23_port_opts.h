/*
 * Options of the POSIX port (pass -Iport/posix
 * -DSE23_CFG_OPTS_FILE='"se23_port_opts.h"'): none; the host libm is used
 * as is. Kept so that every port has the same two files.
 */
#ifndef SE23_PORT_OPTS_H
#define SE23_PORT_OPTS_H
#endif
