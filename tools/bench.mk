# make bench: host instruction counts per routine (valgrind callgrind), float
# and double builds. Included by the top-level Makefile.
.PHONY: bench
BENCH_CFLAGS := $(WARN) -O2 -fno-inline -Iinclude

$(BUILD)/bench-%/se23-bench: tools/bench/bench.c $(BUILD)/lib-host-%/libse23.a
	mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) -DSE23_CFG_DOUBLE=$(if $(filter double,$*),1,0) \
	    $< $(BUILD)/lib-host-$*/libse23.a -lm -o $@

bench: deps $(BUILD)/bench-double/se23-bench $(BUILD)/bench-float/se23-bench
	@echo "host: $$(uname -m), $$(lscpu | sed -n 's/^Model name: *//p'), gcc -O2"
	@sh tools/bench/run.sh $(BUILD)
