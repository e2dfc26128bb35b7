/*
 * Startup for Cortex-M3/M4/M7 images on QEMU's mps2 boards (and any core
 * that boots from a vector table at address 0). QEMU reads the initial SP
 * and PC from this table and ignores the ELF entry point.
 *
 * Reset_Handler: enable the FPU (CPACR, 0xE000ED88, CP10 + CP11 full access)
 * before any floating-point instruction, copy .data from its load address,
 * zero .bss, open the semihosting stdio handles (no crt0 with
 * -nostartfiles), call main() and pass its return value to exit(), which
 * reaches the host as QEMU's exit status through semihosting.
 * Every other exception goes to se23_port_fault() (port/cortex-m/se23_port.c),
 * which reports it and exits with status 255 instead of hanging QEMU.
 * Symbols from the linker script (sections.ld): __stack_top, __data_load,
 * __data_start, __data_end, __bss_start, __bss_end.
 */
    .syntax unified
    .thumb

    .section .vectors, "a", %progbits
    .align 7
    .global se23_vectors
se23_vectors:
    .word __stack_top
    .word Reset_Handler
    .word Default_Handler /* NMI */
    .word Default_Handler /* HardFault */
    .word Default_Handler /* MemManage */
    .word Default_Handler /* BusFault */
    .word Default_Handler /* UsageFault */
    .word 0, 0, 0, 0
    .word Default_Handler /* SVCall */
    .word Default_Handler /* DebugMonitor */
    .word 0
    .word Default_Handler /* PendSV */
    .word Default_Handler /* SysTick */

    .text
    .align 2
    .global Reset_Handler
    .thumb_func
    .type Reset_Handler, %function
Reset_Handler:
#if defined(__ARM_FP)
    ldr r0, =0xE000ED88
    ldr r1, [r0]
    orr r1, r1, #(0xF << 20)
    str r1, [r0]
    dsb
    isb
#endif
    ldr r0, =__data_load
    ldr r1, =__data_start
    ldr r2, =__data_end
1:  cmp r1, r2
    ittt lo
    ldrlo r3, [r0], #4
    strlo r3, [r1], #4
    blo 1b
    ldr r1, =__bss_start
    ldr r2, =__bss_end
    movs r3, #0
2:  cmp r1, r2
    itt lo
    strlo r3, [r1], #4
    blo 2b
    bl initialise_monitor_handles
    bl main
    bl exit
3:  b 3b
    .size Reset_Handler, . - Reset_Handler

    .align 2
    .global Default_Handler
    .thumb_func
    .type Default_Handler, %function
Default_Handler:
    mrs r0, ipsr
    bl se23_port_fault
4:  b 4b
    .size Default_Handler, . - Default_Handler
