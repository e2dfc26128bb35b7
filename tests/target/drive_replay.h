/*
 * A part of the real car drive replayed on the target (drive_replay.c):
 * the rtklibexplorer drive 0708 (tools/data/car/rtklibexplorer-drive-0708,
 * roof IMU at 100 Hz, RTK fixes at 4 Hz) as se23-drive-import writes it,
 * and the host's run of the filter through it in the build's precision
 * (tools/target/gen_drive_replay.c writes drive_replay_data.c: the float
 * reference for the M4F image, the double one for the M7 image).
 *
 * The sequence is an insr_seq_t (ins_replay.h; IMU samples and the fixes,
 * each delivered after the last sample before it in the log, driven by
 * insr_drive), started by se23_ins_align with se23_ins_preset_car's
 * request; the configuration is the preset's at the log's measured rate
 * with the installation (lever arm, mounting, height) set as se23-ins
 * --preset car sets it. Besides its checkpoints, the reference holds the
 * verdict of se23_ins_gnss on every fix.
 */
#ifndef SE23_DRIVE_REPLAY_H
#define SE23_DRIVE_REPLAY_H

#include "ins_replay.h"

/** The reference of the drive. */
typedef struct {
    insr_seq_t seq;
    se23_real_t rate_hz, lat;     /**< se23_ins_preset_car's arguments */
    const signed char *verdict;   /**< se23_ins_gnss's verdict on fix i */
    double outage_s[2];           /**< the fixes left out: from, length [s] (log time) */
} drive_ref_t;

extern const drive_ref_t drive_ref;

#endif /* SE23_DRIVE_REPLAY_H */
