//! Stack high-water mark: paint the free stack with a pattern at start-up, and later find how
//! far down the pattern was overwritten. QEMU has no cycle counter worth reading, but memory
//! use is exact.

use core::sync::atomic::{AtomicUsize, Ordering};

/// The word painted on the free stack.
const PAINT: u32 = 0xDEAD_BEEF;
/// How much stack below the caller's frame is painted (bytes). Far more than the drive needs;
/// the mps2-an386 has 4 MiB of RAM.
const WINDOW: usize = 64 * 1024;
/// Left unpainted just below the current stack pointer, for `paint`'s own frame (bytes).
const GUARD: usize = 256;

/// Lowest painted address (bytes), 0 before [`paint`].
static PAINTED_FROM: AtomicUsize = AtomicUsize::new(0);

unsafe extern "C" {
    /// The initial stack pointer, the top of RAM (cortex-m-rt's `link.x`).
    static _stack_start: u32;
}

/// The top of the stack (address).
fn stack_top() -> usize {
    (&raw const _stack_start) as usize
}

/// Paints `WINDOW` bytes of the free stack below the current frame. Call once, first thing in
/// `main`.
#[inline(never)]
pub fn paint() {
    let sp = cortex_m::register::msp::read() as usize;
    let end = sp.saturating_sub(GUARD);
    let bottom = end.saturating_sub(WINDOW);
    let mut p = bottom;
    while p < end {
        // SAFETY: [end − WINDOW, end) lies below the current stack pointer, in RAM no object
        // occupies (the stack grows down from `_stack_start`, .data/.bss sit at the bottom of
        // RAM, far below), and this loop itself only uses registers.
        unsafe { core::ptr::write_volatile(p as *mut u32, PAINT) };
        p += 4;
    }
    PAINTED_FROM.store(bottom, Ordering::Relaxed);
}

/// The deepest stack use since [`paint`] (bytes from the top of RAM), or `None` if it went
/// past the painted window (or nothing was painted).
pub fn peak() -> Option<usize> {
    let sp = cortex_m::register::msp::read() as usize;
    let bottom = PAINTED_FROM.load(Ordering::Relaxed);
    if bottom == 0 {
        return None;
    }
    let mut p = bottom;
    // SAFETY: reads of words of the painted window below the current stack pointer.
    while p < sp && unsafe { core::ptr::read_volatile(p as *const u32) } == PAINT {
        p += 4;
    }
    (p > bottom).then(|| stack_top().saturating_sub(p))
}
