/**
 * @file replay.h
 * @brief se23-ins's file input: replays a file:// LCM log through the
 *        validating reader of tools/lcm/logfile.h (not LCM's file provider,
 *        which trusts the lengths it reads), so that a corrupt log is
 *        reported and read past instead of crashing the INS.
 */
#ifndef SE23_INS_REPLAY_H
#define SE23_INS_REPLAY_H

#include <lcm/lcm.h>
#include <stdint.h>

/** One input channel: its handler (as for lcm_subscribe) and, for live input,
 *  the subscription's queue capacity (0: LCM's default). */
typedef struct {
    const char *channel;
    lcm_msg_handler_t handler;
    int queue_capacity;
} replay_sub_t;

/**
 * Replays the log of url, "file://PATH[?speed=S]" (S as for LCM's file
 * provider: 0 = flat out, 1 = real time, the default; "mode=r" is accepted),
 * calling the handler of each valid event's channel with user, until the
 * end of the log or until stop(user) is nonzero. Returns the bytes skipped
 * as corrupt (>= 0), or -1 after a message if url or its file is unusable.
 */
int64_t replay_file(const char *url, const replay_sub_t *subs, int n_subs, void *user,
                    int (*stop)(void *user));

#endif /* SE23_INS_REPLAY_H */
