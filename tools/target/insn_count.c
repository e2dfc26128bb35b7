/*
 * insn_count: a QEMU TCG plugin that counts guest instructions between two
 * marker functions of the benchmark image (tools/target/bench_marks.c).
 *
 *   qemu-system-arm ... -plugin insn_count.so,begin=0xADDR,end=0xADDR \
 *                       -d plugin -D LOGFILE
 *
 * Every executed guest instruction adds one to a counter (an inline add
 * attached to each instruction, so the count is exact even when a block is
 * left early). The first instruction of the begin marker snapshots the
 * counter; the first instruction of the end marker prints
 *   region <i> <instructions since the last begin>
 * through qemu_plugin_outs (the -D log). The benchmark prints the region
 * names in the same order; tools/target/bench.py pairs them. The counts are
 * a property of the guest code, identical from run to run.
 *
 * Debian's QEMU 7.2 ships no qemu-plugin.h: the few declarations of the
 * plugin API (version 1) used here are written out below, as in QEMU 7.2's
 * include/qemu/qemu-plugin.h.
 */
#include <inttypes.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- QEMU 7.2 plugin API (subset) ---------------------------------------- */
#define QEMU_PLUGIN_EXPORT __attribute__((visibility("default")))
#define QEMU_PLUGIN_VERSION 1

typedef uint64_t qemu_plugin_id_t;

typedef struct qemu_info_t {
    const char *target_name;
    struct {
        int min;
        int cur;
    } version;
    bool system_emulation;
    union {
        struct {
            int smp_vcpus;
            int max_vcpus;
        } system;
    };
} qemu_info_t;

struct qemu_plugin_tb;
struct qemu_plugin_insn;

enum qemu_plugin_cb_flags {
    QEMU_PLUGIN_CB_NO_REGS,
    QEMU_PLUGIN_CB_R_REGS,
    QEMU_PLUGIN_CB_RW_REGS
};

enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };

typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void *userdata);
typedef void (*qemu_plugin_vcpu_udata_cb_t)(unsigned int vcpu_index, void *userdata);
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id,
                                               struct qemu_plugin_tb *tb);

void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id,
                                           qemu_plugin_vcpu_tb_trans_cb_t cb);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
struct qemu_plugin_insn *qemu_plugin_tb_get_insn(const struct qemu_plugin_tb *tb,
                                                 size_t idx);
uint64_t qemu_plugin_insn_vaddr(const struct qemu_plugin_insn *insn);
void qemu_plugin_register_vcpu_insn_exec_cb(struct qemu_plugin_insn *insn,
                                            qemu_plugin_vcpu_udata_cb_t cb,
                                            enum qemu_plugin_cb_flags flags,
                                            void *userdata);
void qemu_plugin_register_vcpu_insn_exec_inline(struct qemu_plugin_insn *insn,
                                                enum qemu_plugin_op op, void *ptr,
                                                uint64_t imm);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb,
                                    void *userdata);
void qemu_plugin_outs(const char *string);

QEMU_PLUGIN_EXPORT int qemu_plugin_version = QEMU_PLUGIN_VERSION;
QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info,
                                           int argc, char **argv);

/* ---- the counter ------------------------------------------------------------ */

static uint64_t insns;     /* every executed instruction (one vCPU) */
static uint64_t start;     /* insns at the last begin marker */
static uint64_t begin_pc;  /* first instruction of the begin marker */
static uint64_t end_pc;    /* first instruction of the end marker */
static unsigned regions;
static int open_region;

static void on_begin(unsigned int vcpu, void *udata)
{
    (void)vcpu;
    (void)udata;
    start = insns;
    open_region = 1;
}

static void on_end(unsigned int vcpu, void *udata)
{
    char line[64];
    (void)vcpu;
    (void)udata;
    if (!open_region) {
        qemu_plugin_outs("insn_count: end marker without begin\n");
        return;
    }
    open_region = 0;
    snprintf(line, sizeof line, "region %u %" PRIu64 "\n", regions++, insns - start);
    qemu_plugin_outs(line);
}

static void on_tb(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    size_t n = qemu_plugin_tb_n_insns(tb);
    size_t i;
    (void)id;
    for (i = 0; i < n; ++i) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        uint64_t pc = qemu_plugin_insn_vaddr(insn);
        qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64,
                                                   &insns, 1);
        if (pc == begin_pc) {
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_begin, QEMU_PLUGIN_CB_NO_REGS,
                                                   NULL);
        } else if (pc == end_pc) {
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_end, QEMU_PLUGIN_CB_NO_REGS,
                                                   NULL);
        }
    }
}

static void on_exit(qemu_plugin_id_t id, void *udata)
{
    char line[80];
    (void)id;
    (void)udata;
    snprintf(line, sizeof line, "total %" PRIu64 " regions %u\n", insns, regions);
    qemu_plugin_outs(line);
}

/* begin=ADDR,end=ADDR (hex or decimal; the Thumb bit is ignored). */
QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info,
                                           int argc, char **argv)
{
    int i;
    (void)info;
    for (i = 0; i < argc; ++i) {
        if (strncmp(argv[i], "begin=", 6) == 0) {
            begin_pc = strtoull(argv[i] + 6, NULL, 0) & ~(uint64_t)1;
        } else if (strncmp(argv[i], "end=", 4) == 0) {
            end_pc = strtoull(argv[i] + 4, NULL, 0) & ~(uint64_t)1;
        } else {
            fprintf(stderr, "insn_count: unknown argument %s\n", argv[i]);
            return -1;
        }
    }
    if (begin_pc == 0 || end_pc == 0) {
        fprintf(stderr, "insn_count: need begin=ADDR,end=ADDR\n");
        return -1;
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_tb);
    qemu_plugin_register_atexit_cb(id, on_exit, NULL);
    return 0;
}
