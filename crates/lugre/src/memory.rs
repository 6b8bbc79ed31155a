//! Large output vectors backed by transparent huge pages.
//!
//! Writing tens of MB of fresh memory costs one page fault per 4 KiB page, and a fault with its
//! zeroing costs microseconds in a virtual machine: at 10^6 turning points that was 40 % of the
//! time of [`crate::HysteresisLoop::new`]. With huge pages it is one fault per 2 MiB.

/// Outputs of this many bytes or more get huge pages.
const HUGE_FROM: usize = HUGE_PAGE;

const HUGE_PAGE: usize = 2 << 20;

/// An empty vector with room for `n` elements. A large one (2 MiB or more) gets room for all
/// `n` at once, when that much address space can be had, and the kernel is asked to back it
/// with huge pages: only the pages written are ever backed, there is no reallocation, and
/// writing fresh memory takes one page fault per 2 MiB rather than per 4 KiB. Trim with
/// `shrink_to_fit` once filled if `n` was only a bound.
pub fn column<T>(n: usize) -> Vec<T> {
    let mut v = Vec::new();
    if n.saturating_mul(std::mem::size_of::<T>()) >= HUGE_FROM {
        if v.try_reserve_exact(n).is_ok() {
            advise_huge_pages(&mut v);
        }
    } else {
        v.reserve_exact(n);
    }
    v
}

/// Asks for transparent huge pages over the capacity of a vector (as numpy does for its
/// arrays of 4 MiB or more). A kernel without them ignores the advice.
#[cfg(target_os = "linux")]
fn advise_huge_pages<T>(v: &mut Vec<T>) {
    const PAGE: usize = 4096;
    let bytes = v.capacity().saturating_mul(std::mem::size_of::<T>());
    let start = v.as_mut_ptr() as usize;
    let (lo, hi) = (start.next_multiple_of(PAGE), (start + bytes) / PAGE * PAGE);
    if hi > lo {
        // SAFETY: `lo..hi` lies within the vector's allocation (whole pages of it); the advice
        // changes how the kernel backs those pages, never their contents. A failure (no THP
        // support) leaves the memory as it was.
        unsafe {
            libc::madvise(lo as *mut libc::c_void, hi - lo, libc::MADV_HUGEPAGE);
        }
    }
}

#[cfg(not(target_os = "linux"))]
fn advise_huge_pages<T>(_v: &mut Vec<T>) {}
