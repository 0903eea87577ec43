//! Object names (buffer objects, queries, ...): what glGen* hands out.

use std::collections::BTreeSet;

/// `count` names that neither an object (`in_use`) nor an earlier glGen* (`reserved`) holds,
/// counting up from the largest name in use, as Mesa does; they join `reserved` until bound.
///
/// # Examples
///
/// ```
/// use fflight::state::names::generate;
/// use std::collections::BTreeSet;
/// let mut reserved = BTreeSet::new();
/// assert_eq!(generate([3, 7].into_iter(), &mut reserved, 2), [8, 9]);
/// assert_eq!(generate([3, 7].into_iter(), &mut reserved, 1), [10]); // 8 and 9 are reserved
/// ```
pub fn generate(
    in_use: impl Iterator<Item = u32>,
    reserved: &mut BTreeSet<u32>,
    count: usize,
) -> Vec<u32> {
    let largest = in_use.chain(reserved.iter().copied()).max();
    let first = largest.unwrap_or(0).saturating_add(1);
    let names: Vec<u32> = (first..=u32::MAX).take(count).collect();
    reserved.extend(&names);
    names
}
