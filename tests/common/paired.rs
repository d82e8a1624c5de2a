//! The one way the tests zip two sequences they compare ([`paired`]): a plain `zip` stops at the shorter one, so a
//! comparison of a run's nodes with an empty or short run (a failed solve, a lost row) passes on what little there
//! is. Included with `#[path = "common/paired.rs"] mod paired;`.

#![allow(dead_code)]

/// The pairs `(a_i, b_i)` of two sequences a test compares, after asserting that both are non-empty and of the same
/// length (the caller's line is reported).
#[track_caller]
pub fn paired<A, B>(a: A, b: B) -> std::iter::Zip<A::IntoIter, B::IntoIter>
where
    A: IntoIterator,
    B: IntoIterator,
    A::IntoIter: ExactSizeIterator,
    B::IntoIter: ExactSizeIterator,
{
    let (a, b) = (a.into_iter(), b.into_iter());
    assert!(a.len() > 0, "nothing to compare: the first sequence is empty ({} items in the second)", b.len());
    assert_eq!(a.len(), b.len(), "the compared sequences differ in length");
    a.zip(b)
}

#[cfg(test)]
mod tests {
    use super::paired;

    #[test]
    fn pairs_equal_sequences_and_refuses_empty_or_unequal_ones() {
        assert_eq!(paired(&[1, 2], &[3, 4]).map(|(a, b)| a * b).sum::<i32>(), 11);
        assert!(std::panic::catch_unwind(|| paired(Vec::<i32>::new(), Vec::<i32>::new()).count()).is_err());
        assert!(std::panic::catch_unwind(|| paired(vec![1], vec![1, 2]).count()).is_err());
        assert!(std::panic::catch_unwind(|| paired(vec![1, 2], vec![1]).count()).is_err());
    }
}
