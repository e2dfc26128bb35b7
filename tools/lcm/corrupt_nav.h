/**
 * @file corrupt_nav.h
 * @brief se23-corrupt --nav: plants impossible values (NaN, non-rotations,
 *        negative variances, impossible status) in whole nav states and
 *        truth records of a log, which se23-report's screening must leave
 *        out; see corrupt_nav.c for the cases.
 */
#ifndef SE23_CORRUPT_NAV_H
#define SE23_CORRUPT_NAV_H

/**
 * Copies the log in to out with the cases planted and prints the records
 * se23-report must leave out ("expect nav|truth <reason> <count>").
 * Returns the exit status: 0, or 1 after a message.
 */
int corrupt_nav(const char *in, const char *out);

#endif /* SE23_CORRUPT_NAV_H */
