//! Object names (buffer objects, queries, ...): what glGen* hands out.

use std::collections::BTreeSet;

/// `count` names that neither an object (`in_use`) nor an earlier glGen* (`reserved`) holds,
/// counting up from the largest name in use, as Mesa does; they join `reserved` until bound.
/// When that count reaches the largest name (an application bound 0xFFFFFFFF), the rest are
/// the lowest free names. Fewer than `count` only when the name space is exhausted: the
/// caller reports GL_OUT_OF_MEMORY.
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
    in_use: impl Iterator<Item = u32> + Clone,
    reserved: &mut BTreeSet<u32>,
    count: usize,
) -> Vec<u32> {
    if count == 0 {
        return Vec::new();
    }
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
    fn names_after_the_last_one_start_again_from_1() {
        // Found by the entry-point sweep: glBindTexture(target, 0xFFFFFFFF) then glGenTextures
        // gave one name (the one in use) for any count.
        let mut reserved = BTreeSet::new();
        let names = generate([u32::MAX, 2].into_iter(), &mut reserved, 3);
        assert_eq!(names, vec![1, 3, 4]);
        assert_eq!(generate([u32::MAX].into_iter(), &mut reserved, 1), vec![2]);
        assert_eq!(
            generate([7].into_iter(), &mut BTreeSet::new(), 2),
            vec![8, 9]
        );
    }

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
