/**
 * @file corrupt_framing.h
 * @brief se23-corrupt --framing: breaks the event framing of an LCM log
 *        (lengths, sync words, stray bytes), which tools/lcm/logfile.c must
 *        read past; see corrupt_framing.c for the cases.
 */
#ifndef SE23_CORRUPT_FRAMING_H
#define SE23_CORRUPT_FRAMING_H

/**
 * Copies the clean log in to out with the framing cases injected and prints
 * the counters se23-ins must report on out ("expect <counter> <value>").
 * Returns the exit status: 0, or 1 after a message.
 */
int corrupt_framing(const char *in, const char *out);

#endif /* SE23_CORRUPT_FRAMING_H */
