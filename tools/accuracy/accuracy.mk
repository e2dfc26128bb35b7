# make accuracy: position/velocity errors of the float and double builds
# after 60 s and 1 h against a long-double truth, MEMS-grade and
# navigation-grade scenarios with the Earth rate, exact vs three first-order
# increments: Forster et al.'s, the paper's remark as printed and the paper's
# eq. backtofuture (tools/doc/pages/propagation.md). Included by the
# top-level Makefile; takes about 15 s.
.PHONY: accuracy
ACC_SRCS := tools/accuracy/accuracy.c tools/accuracy/scenario.c tools/accuracy/truth.c
ACC_HDRS := tools/accuracy/scenario.h tools/accuracy/truth.h

$(BUILD)/accuracy/accuracy-%: $(ACC_SRCS) $(ACC_HDRS) $(BUILD)/lib-host-%/libse23.a
	mkdir -p $(dir $@)
	$(CC) $(WARN) -O2 -Iinclude -DSE23_CFG_DOUBLE=$(if $(filter double,$*),1,0) \
	    $(ACC_SRCS) $(BUILD)/lib-host-$*/libse23.a -lm -o $@

accuracy: $(BUILD)/accuracy/accuracy-double $(BUILD)/accuracy/accuracy-float
	@$(BUILD)/accuracy/accuracy-double header && $(BUILD)/accuracy/accuracy-float
