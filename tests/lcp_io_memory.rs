//! The LCP file parser ([`rollbem::lcp_io::parse`]) reserves memory in proportion to the text it has read, not to
//! the sizes a file declares (fuzz target `lcp_file`; inputs in `fuzz/regressions/`). Before the fix a file of a
//! few bytes declaring n = 20000 reserved the dense 20000² matrix (3.2 GB) before reading one entry, dense or
//! sparse-block, and a sparse-block file declaring 20000 × 20000 blocks a 400 MB table of them.
//!
//! A global allocator that forwards to the system's records, per thread, the largest single request: each test
//! bounds what parsing one hostile file may ask for.

use rollbem::lcp_io;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::path::Path;

struct RecordLargest;

thread_local! {
    static LARGEST: Cell<usize> = const { Cell::new(0) };
}

fn record(size: usize) {
    // `try_with`: nothing to record while the thread's locals are being torn down.
    let _ = LARGEST.try_with(|l| l.set(l.get().max(size)));
}

// SAFETY: every call is forwarded unchanged to `System`; recording touches only a `Cell` of the current thread.
unsafe impl GlobalAlloc for RecordLargest {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        record(layout.size());
        unsafe { System.alloc(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        record(layout.size());
        unsafe { System.alloc_zeroed(layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        record(new_size);
        unsafe { System.realloc(ptr, layout, new_size) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: RecordLargest = RecordLargest;

/// Parse `text` and return the error message and the largest single allocation made meanwhile (bytes).
fn parse_error_and_largest(text: &str) -> (String, usize) {
    LARGEST.with(|l| l.set(0));
    let message = match lcp_io::parse(text, Path::new("hostile.dat")) {
        Ok(lcp) => panic!("a file that declares more than it holds was read as a {}-size LCP", lcp.size()),
        Err(e) => e.to_string(),
    };
    (message, LARGEST.with(Cell::get))
}

fn regression(name: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/regressions").join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Generous bound on one allocation while reading a file of `len` bytes: the error message, the line index and the
/// few vectors of numbers read so far are all within a small multiple of the text.
fn proportional(len: usize) -> usize {
    64 * len + 4096
}

#[test]
fn a_truncated_dense_file_declaring_n_20000_reserves_no_dense_matrix() {
    let text = regression("lcp-dense-n20000-truncated.dat");
    let (message, largest) = parse_error_and_largest(&text);
    assert!(message.contains("unexpected end of file"), "{message}");
    assert!(largest <= proportional(text.len()), "{largest} bytes requested for a {}-byte file", text.len());
}

#[test]
fn a_truncated_sparse_block_file_declaring_n_20000_reserves_no_dense_matrix() {
    let text = regression("lcp-sparse-n20000-truncated.dat");
    let (message, largest) = parse_error_and_largest(&text);
    assert!(message.contains("unexpected end of file"), "{message}");
    assert!(largest <= proportional(text.len()), "{largest} bytes requested for a {}-byte file", text.len());
}

#[test]
fn a_sparse_block_file_with_20000_by_20000_blocks_reserves_no_block_table() {
    // n = 20000 in 20000 × 20000 blocks of 1 × 1 (cumulative sizes 1, 2, …, 20000 for rows and columns), two stored
    // blocks in block row 0, then the file stops. The old parser allocated the dense M (3.2 GB) first, then one
    // flag per block position (400 MB) to find blocks stored twice.
    let sizes: String = (1..=20000).map(|k| format!("{k} ")).collect();
    let text = format!("20000 1 20000 20000\n2 20000 20000\n{sizes}\n{sizes}\n2 2\n0 2\n0 1\n");
    let (message, largest) = parse_error_and_largest(&text);
    assert!(message.contains("unexpected end of file"), "{message}");
    assert!(largest <= proportional(text.len()), "{largest} bytes requested for a {}-byte file", text.len());
}
