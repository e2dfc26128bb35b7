# Real car drives (issue 35): se23-drive-import (a drive's files -> one LCM
# log + a sidecar) and se23-drive (the report against the reference).
# Included by tools/harness.mk (H, H_BIN, H_COMMON, H_LIB, h_objs come from
# there).
#
#   make drive-tools   builds se23-drive-import, se23-drive and se23-drive-synth
#                      (a nav log with known errors, for the self-test) into $(H_BIN)
#   make drive-selftest  tools/drive/selftest.sh on fabricated drives

H_DRIVE_IMPORT_SRCS := tools/drive/import.c tools/drive/import_read.c tools/import/csv.c \
                       tools/import/row.c tools/import/hygiene.c tools/import/gyrocheck.c \
                       $(H_COMMON)
H_DRIVE_REPORT_SRCS := tools/drive/report.c tools/drive/import_read.c tools/import/csv.c \
                       tools/import/row.c tools/import/hygiene.c tools/report/logread.c \
                       tools/report/metrics.c tools/lcm/logfile.c $(H_COMMON)
H_DRIVE_SYNTH_SRCS := tools/drive/synth.c tools/drive/import_read.c tools/import/csv.c \
                      tools/import/row.c tools/import/hygiene.c tools/lcm/logfile.c $(H_COMMON)
H_HDRS += $(wildcard tools/drive/*.h)

.PHONY: drive-tools drive-selftest

drive-tools: $(H_BIN)/se23-drive-import $(H_BIN)/se23-drive $(H_BIN)/se23-drive-synth

$(H_BIN)/se23-drive-import: $(call h_objs,$(H_DRIVE_IMPORT_SRCS)) $(H)/libse23lcm.a $(H_LIB)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm
$(H_BIN)/se23-drive: $(call h_objs,$(H_DRIVE_REPORT_SRCS)) $(H)/libse23lcm.a $(H_LIB)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm

$(H_BIN)/se23-drive-synth: $(call h_objs,$(H_DRIVE_SYNTH_SRCS)) $(H)/libse23lcm.a
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm

drive-selftest: drive-tools
	@sh tools/drive/selftest.sh $(H)
