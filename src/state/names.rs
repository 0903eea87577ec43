//! Object names (buffer objects, queries, ...): what glGen* hands out.

use std::collections::BTreeSet;

/// `count` names that neither an object (`in_use`) nor an earlier glGen* (`reserved`) holds,
/// counting up from the largest name in use, as Mesa does; they join `reserved` until bound.
/// When that count reaches the largest name (an application bound 0xFFFFFFFF), the rest are
/// the lowest free names. Fewer than `count` only when the name space is exhausted: the
/// caller reports GL_OUT_OF_MEMORY.
pub fn generate(
    in_use: impl Iterator<Item = u32> + Clone,
    reserved: &mut BTreeSet<u32>,
    count: usize,
) -> Vec<u32> {
    let largest = in_use.clone().chain(reserved.iter().copied()).max();
    let first = largest.map_or(Some(1), |largest| largest.checked_add(1));
    let mut names: Vec<u32> = first
        .map(|first| (first..=u32::MAX).take(count).collect())
        .unwrap_or_default();
    if names.len() < count {
        let used: BTreeSet<u32> = in_use.chain(names.iter().copied()).collect();
        let free = (1..=u32::MAX).filter(|n| !used.contains(n) && !reserved.contains(n));
        names.extend(free.take(count - names.len()));
    }
    reserved.extend(&names);
    names
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_past_the_largest_wrap_to_the_lowest_free_ones() {
        let mut reserved = BTreeSet::new();
        let in_use = [u32::MAX - 1, 2];
        let names = generate(in_use.iter().copied(), &mut reserved, 4);
        assert_eq!(names, [u32::MAX, 1, 3, 4]);
        let in_use = [u32::MAX, 2];
        assert_eq!(generate(in_use.iter().copied(), &mut reserved, 2), [5, 6]);
    }
}
