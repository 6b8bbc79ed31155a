//! Large output vectors backed by transparent huge pages (feature `huge-pages`, on by
//! default; without it, plain allocations of the same sizes).
//!
//! Writing tens of MB of fresh memory costs one page fault per 4 KiB page, and a fault with its
//! zeroing costs microseconds in a virtual machine (a large part of
//! [`crate::HysteresisLoop::new`] at 10^6 turning points: BENCHMARKS.md). With huge pages it is
//! one fault per 2 MiB.

/// A transparent huge page; outputs of at least this many bytes get them.
const HUGE_PAGE: usize = 2 << 20;

/// An empty vector with room for `n` elements. A large one (2 MiB or more) gets room for all
/// `n` at once, when that much address space can be had, and the kernel is asked to back it
/// with huge pages: only the pages written are ever backed, there is no reallocation, and
/// writing fresh memory takes one page fault per 2 MiB rather than per 4 KiB. Trim with
/// `shrink_to_fit` once filled if `n` was only a bound.
pub(crate) fn column<T>(n: usize) -> Vec<T> {
    let mut v = Vec::new();
    if n.saturating_mul(std::mem::size_of::<T>()) >= HUGE_PAGE {
        if v.try_reserve_exact(n).is_ok() {
            advise_huge_pages(v.spare_capacity_mut());
        }
    } else {
        v.reserve_exact(n);
    }
    v
}

/// Asks for transparent huge pages over the memory of a slice (as numpy does for its arrays
/// of 4 MiB or more). A kernel without them ignores the advice.
#[cfg(all(target_os = "linux", feature = "huge-pages"))]
fn advise_huge_pages<T>(v: &mut [T]) {
    const PAGE: usize = 4096;
    let bytes = std::mem::size_of_val(v);
    let start = v.as_mut_ptr() as usize;
    let (lo, hi) = (start.next_multiple_of(PAGE), (start + bytes) / PAGE * PAGE);
    if hi > lo {
        // SAFETY: `lo..hi` lies within the slice's memory (whole pages of it); the advice
        // changes how the kernel backs those pages, never their contents. A failure (no THP
        // support) leaves the memory as it was.
        unsafe {
            libc::madvise(lo as *mut libc::c_void, hi - lo, libc::MADV_HUGEPAGE);
        }
    }
}

#[cfg(not(all(target_os = "linux", feature = "huge-pages")))]
fn advise_huge_pages<T>(_v: &mut [T]) {}

/// `count` columns of `len` elements each, zeroed, in one allocation backed by huge pages,
/// the first column starting on a huge-page boundary: writing them takes one page fault per
/// 2 MiB and none for the slack around them. (Separate vectors each start and end inside a
/// huge page, whose remainder the kernel backs with 4 KiB pages: about 500 faults a vector.)
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Columns<T> {
    buf: Vec<T>,
    offset: usize,
    len: usize,
}

impl<T: Copy + Default> Columns<T> {
    /// Zeroed columns. Zeroed memory comes from the kernel untouched (`calloc`), so the slack
    /// is never written.
    pub fn zeroed(count: usize, len: usize) -> Self {
        let size = std::mem::size_of::<T>().max(1);
        let slack = HUGE_PAGE / size;
        let total = count.saturating_mul(len);
        let large = total.saturating_mul(size) >= HUGE_PAGE;
        let mut buf = vec![T::default(); if large { total + 2 * slack } else { total }];
        let mut offset = 0;
        if large {
            advise_huge_pages(&mut buf);
            let start = buf.as_ptr() as usize;
            offset = (start.next_multiple_of(HUGE_PAGE) - start) / size;
        }
        Self { buf, offset, len }
    }

    #[inline]
    pub fn column(&self, i: usize) -> &[T] {
        let from = self.offset + i * self.len;
        &self.buf[from..from + self.len]
    }

    #[inline]
    pub fn column_mut(&mut self, i: usize) -> &mut [T] {
        let from = self.offset + i * self.len;
        &mut self.buf[from..from + self.len]
    }
}
