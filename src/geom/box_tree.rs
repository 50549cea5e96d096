//! A bounding-volume hierarchy over items with axis-aligned boxes, and the search for every pair
//! of items whose boxes overlap.
//!
//! The tree splits its items at the median of their box centres along the widest extent of
//! those centres, down to leaves of at most [`LEAF_SIZE`] items: its depth is `log2(n / 4)`
//! whatever the items' shape, so building it takes O(n log n). Pairs are found by walking the
//! tree against itself (each pair of overlapping subtrees once), O(n log n + k) for `k`
//! overlapping pairs of boxes on the meshes this serves; the walk is split into independent
//! tasks that run in parallel with the `parallel` feature.

use super::parallel::{join, map_indexed};

/// Items per leaf, at most.
const LEAF_SIZE: usize = 4;

/// Subtrees of at most this many items are built on one thread, and a search task covers at most
/// this many items: tasks then take tenths of a millisecond, well above their scheduling cost.
const TASK_ITEMS: u32 = 1 << 12;

/// An axis-aligned box, closed: boxes that touch overlap.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct BoundingBox {
    pub(crate) min: [f64; 3],
    pub(crate) max: [f64; 3],
}

impl BoundingBox {
    /// The smallest box holding `points` (which are finite and not empty).
    pub(crate) fn of_points(points: &[[f64; 3]]) -> BoundingBox {
        let mut bounds = BoundingBox {
            min: points[0],
            max: points[0],
        };
        for p in &points[1..] {
            bounds = bounds.union(&BoundingBox { min: *p, max: *p });
        }
        bounds
    }

    /// The box grown to hold `point`.
    #[inline]
    pub(crate) fn extend(&mut self, point: [f64; 3]) {
        for (k, &x) in point.iter().enumerate() {
            self.min[k] = self.min[k].min(x);
            self.max[k] = self.max[k].max(x);
        }
    }

    /// The smallest box holding both.
    pub(crate) fn union(&self, other: &BoundingBox) -> BoundingBox {
        BoundingBox {
            min: [0, 1, 2].map(|k| self.min[k].min(other.min[k])),
            max: [0, 1, 2].map(|k| self.max[k].max(other.max[k])),
        }
    }

    /// Do the closed boxes have a point in common?
    #[inline]
    pub(crate) fn overlaps(&self, other: &BoundingBox) -> bool {
        (0..3).all(|k| self.min[k] <= other.max[k] && other.min[k] <= self.max[k])
    }

    /// The centre, halved before the sum so that it cannot overflow.
    fn centre(&self) -> [f64; 3] {
        [0, 1, 2].map(|k| 0.5 * self.min[k] + 0.5 * self.max[k])
    }
}

/// An item the tree can hold.
pub(crate) trait Boxed {
    /// The item's box.
    fn bounding_box(&self) -> &BoundingBox;
}

/// A node: its items are `items[start..start + len]`. A leaf holds at most [`LEAF_SIZE`] items;
/// an inner node's children are the next node and node `right`, splitting its items in half.
#[derive(Clone, Copy, Debug, Default)]
struct Node {
    bounds: BoundingBox,
    start: u32,
    len: u32,
    right: u32,
}

impl Node {
    fn is_leaf(&self) -> bool {
        self.len as usize <= LEAF_SIZE
    }
}

/// The items, reordered so that every node's items are contiguous, and the nodes, depth first
/// from the root.
#[derive(Debug)]
pub(crate) struct BoxTree<T> {
    items: Vec<T>,
    nodes: Vec<Node>,
}

/// A unit of the pair search: the pairs within one subtree, or between two.
#[derive(Clone, Copy, Debug)]
enum Task {
    Within(u32),
    Between(u32, u32),
}

impl<T: Boxed + Copy + Send + Sync> BoxTree<T> {
    /// The tree over `items` (fewer than `u32::MAX`).
    pub(crate) fn new(items: Vec<T>) -> Self {
        // The splits move compact keys, not the items, which then move once, into leaf order.
        // Splits need no exact centres: single precision, once brought near 1 by a power of two
        // (so that no centre overflows it), places them well enough.
        let largest = items.iter().fold(0.0f64, |m, item| {
            let b = item.bounding_box();
            (0..3).fold(m, |m, k| m.max(b.min[k].abs()).max(b.max[k].abs()))
        });
        let scale = if largest > 0.0 {
            1.0 / power_of_two_above(largest)
        } else {
            1.0
        };
        let mut keys = map_indexed(items.len(), |i| Key {
            centre: items[i].bounding_box().centre().map(|c| (c * scale) as f32),
            item: i as u32,
        });
        let mut nodes = vec![Node::default(); node_count(items.len())];
        if !items.is_empty() {
            build(&mut nodes, 0, &mut keys, 0, &items);
        }
        let items = map_indexed(keys.len(), |k| items[keys[k].item as usize]);
        BoxTree { items, nodes }
    }

    /// `visit(item)` for every item whose box overlaps `bounds`: O(log n + k) for `k` such
    /// items on the meshes this serves.
    pub(crate) fn visit_overlapping(&self, bounds: &BoundingBox, mut visit: impl FnMut(&T)) {
        if self.items.is_empty() {
            return;
        }
        let mut stack = vec![0u32];
        while let Some(index) = stack.pop() {
            let node = &self.nodes[index as usize];
            if !node.bounds.overlaps(bounds) {
                continue;
            }
            if node.is_leaf() {
                let items = &self.items[node.start as usize..(node.start + node.len) as usize];
                for item in items.iter().filter(|i| i.bounding_box().overlaps(bounds)) {
                    visit(item);
                }
            } else {
                let (left, right) = self.children(index);
                stack.extend([left, right]);
            }
        }
    }

    /// The number of items.
    pub(crate) fn len(&self) -> usize {
        self.items.len()
    }

    /// The items, in the tree's order.
    pub(crate) fn into_items(self) -> Vec<T> {
        self.items
    }

    /// `test(a, b)` for every pair of distinct items whose boxes overlap, each pair once in an
    /// unspecified order (and either way round); the `Some` results, in an unspecified order.
    pub(crate) fn overlapping_pairs<R: Send>(
        &self,
        test: impl Fn(&T, &T) -> Option<R> + Sync,
    ) -> Vec<R> {
        let tasks = self.tasks();
        let run = |task: &Task| {
            let mut found = Vec::new();
            match *task {
                Task::Within(node) => self.pairs_within(node, &test, &mut found),
                Task::Between(a, b) => self.pairs_between(a, b, &test, &mut found),
            }
            found
        };
        #[cfg(feature = "parallel")]
        if rayon::current_num_threads() > 1 {
            use rayon::prelude::*;
            return tasks.par_iter().flat_map_iter(run).collect();
        }
        tasks.iter().flat_map(run).collect()
    }

    /// The search split into tasks of at most [`TASK_ITEMS`] items (or of two leaves).
    fn tasks(&self) -> Vec<Task> {
        let mut tasks = Vec::new();
        let mut pending = Vec::new();
        if !self.nodes.is_empty() {
            pending.push(Task::Within(0));
        }
        while let Some(task) = pending.pop() {
            match task {
                Task::Within(node) => {
                    if self.nodes[node as usize].len <= TASK_ITEMS {
                        tasks.push(task);
                    } else {
                        let (left, right) = self.children(node);
                        pending.extend([
                            Task::Within(left),
                            Task::Within(right),
                            Task::Between(left, right),
                        ]);
                    }
                }
                Task::Between(a, b) => {
                    let (na, nb) = (&self.nodes[a as usize], &self.nodes[b as usize]);
                    if !na.bounds.overlaps(&nb.bounds) {
                        continue;
                    }
                    if na.len + nb.len <= TASK_ITEMS || (na.is_leaf() && nb.is_leaf()) {
                        tasks.push(task);
                    } else {
                        let [(x, y), (z, w)] = self.split_larger(a, b);
                        pending.extend([Task::Between(x, y), Task::Between(z, w)]);
                    }
                }
            }
        }
        tasks
    }

    fn pairs_within<R>(&self, node: u32, test: &impl Fn(&T, &T) -> Option<R>, found: &mut Vec<R>) {
        let n = &self.nodes[node as usize];
        if n.is_leaf() {
            let items = &self.items[n.start as usize..(n.start + n.len) as usize];
            for (i, a) in items.iter().enumerate() {
                for b in &items[i + 1..] {
                    if a.bounding_box().overlaps(b.bounding_box()) {
                        found.extend(test(a, b));
                    }
                }
            }
            return;
        }
        let (left, right) = self.children(node);
        self.pairs_within(left, test, found);
        self.pairs_within(right, test, found);
        self.pairs_between(left, right, test, found);
    }

    fn pairs_between<R>(
        &self,
        a: u32,
        b: u32,
        test: &impl Fn(&T, &T) -> Option<R>,
        found: &mut Vec<R>,
    ) {
        let (na, nb) = (&self.nodes[a as usize], &self.nodes[b as usize]);
        if !na.bounds.overlaps(&nb.bounds) {
            return;
        }
        if na.is_leaf() && nb.is_leaf() {
            let items_b = &self.items[nb.start as usize..(nb.start + nb.len) as usize];
            for x in &self.items[na.start as usize..(na.start + na.len) as usize] {
                if !x.bounding_box().overlaps(&nb.bounds) {
                    continue;
                }
                for y in items_b {
                    if x.bounding_box().overlaps(y.bounding_box()) {
                        found.extend(test(x, y));
                    }
                }
            }
            return;
        }
        for (x, y) in self.split_larger(a, b) {
            self.pairs_between(x, y, test, found);
        }
    }

    /// Nodes `a` and `b` (not both leaves) as two pairs of nodes: the larger one's children,
    /// each with the other node.
    fn split_larger(&self, a: u32, b: u32) -> [(u32, u32); 2] {
        let (na, nb) = (&self.nodes[a as usize], &self.nodes[b as usize]);
        if !na.is_leaf() && (nb.is_leaf() || na.len >= nb.len) {
            let (left, right) = self.children(a);
            [(left, b), (right, b)]
        } else {
            let (left, right) = self.children(b);
            [(a, left), (a, right)]
        }
    }

    fn children(&self, node: u32) -> (u32, u32) {
        (node + 1, self.nodes[node as usize].right)
    }
}

/// An item's box centre, and its index among the items.
#[derive(Clone, Copy, Debug)]
struct Key {
    centre: [f32; 3],
    item: u32,
}

/// Builds the subtree of the items of `keys` (those from `start` on in leaf order) into `nodes`,
/// whose first node is node `index` of the tree.
fn build<T: Boxed + Sync>(
    nodes: &mut [Node],
    index: u32,
    keys: &mut [Key],
    start: u32,
    items: &[T],
) {
    let len = keys.len();
    if len <= LEAF_SIZE {
        let bounds = |key: &Key| *items[key.item as usize].bounding_box();
        let bounds = keys[1..]
            .iter()
            .fold(bounds(&keys[0]), |b, key| b.union(&bounds(key)));
        nodes[0] = Node {
            bounds,
            start,
            len: len as u32,
            right: 0,
        };
        return;
    }
    let axis = widest_axis(keys);
    let half = len / 2;
    keys.select_nth_unstable_by(half, |a, b| a.centre[axis].total_cmp(&b.centre[axis]));
    let left_nodes = node_count(half);
    let (node, children) = nodes.split_first_mut().expect("a node for every subtree");
    let (left, right) = children.split_at_mut(left_nodes);
    let (left_keys, right_keys) = keys.split_at_mut(half);
    let right_index = index + 1 + left_nodes as u32;
    let right_start = start + half as u32;
    if len > TASK_ITEMS as usize {
        join(
            || build(left, index + 1, left_keys, start, items),
            || build(right, right_index, right_keys, right_start, items),
        );
    } else {
        build(left, index + 1, left_keys, start, items);
        build(right, right_index, right_keys, right_start, items);
    }
    *node = Node {
        bounds: left[0].bounds.union(&right[0].bounds),
        start,
        len: len as u32,
        right: right_index,
    };
}

/// The axis along which the keys' centres spread the most.
fn widest_axis(keys: &[Key]) -> usize {
    let (mut low, mut high) = (keys[0].centre, keys[0].centre);
    for key in &keys[1..] {
        for k in 0..3 {
            low[k] = low[k].min(key.centre[k]);
            high[k] = high[k].max(key.centre[k]);
        }
    }
    let extent = [0, 1, 2].map(|k| high[k] - low[k]);
    (0..3)
        .max_by(|&i, &j| extent[i].total_cmp(&extent[j]))
        .unwrap_or(0)
}

/// The smallest power of two above `x` (finite, positive).
fn power_of_two_above(x: f64) -> f64 {
    let exponent = ((x.to_bits() >> 52) & 0x7ff) as i32 - 1022;
    f64::from_bits(((1023 + exponent.clamp(-1022, 1023)) as u64) << 52)
}

/// Nodes of a tree over `items` items: halving splits give subtrees of two sizes only, `s` and
/// `s + 1`, at each depth, so the count takes one step per level.
fn node_count(items: usize) -> usize {
    if items == 0 {
        return 0;
    }
    // (size, subtrees of that size) at the current depth.
    let mut level = [(items, 1usize), (items + 1, 0)];
    let mut nodes = 0;
    loop {
        nodes += level[0].1 + level[1].1;
        let smallest_half = level[0].0 / 2;
        let mut next = [(smallest_half, 0), (smallest_half + 1, 0)];
        for (size, count) in level {
            if count > 0 && size > LEAF_SIZE {
                for half in [size / 2, size - size / 2] {
                    next[half - smallest_half].1 += count;
                }
            }
        }
        if next[0].1 + next[1].1 == 0 {
            return nodes;
        }
        level = next;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Clone, Copy, Debug)]
    struct Item(u32, BoundingBox);

    impl Boxed for Item {
        fn bounding_box(&self) -> &BoundingBox {
            &self.1
        }
    }

    fn recursive_node_count(items: usize) -> usize {
        if items <= LEAF_SIZE {
            1
        } else {
            1 + recursive_node_count(items / 2) + recursive_node_count(items - items / 2)
        }
    }

    #[test]
    fn node_count_matches_the_recursive_definition() {
        for items in 1..3000 {
            assert_eq!(node_count(items), recursive_node_count(items), "{items}");
        }
        assert_eq!(node_count(0), 0);
    }

    /// Boxes of several shapes, including many identical ones and some touching only at a
    /// face or a corner: the tree finds exactly the pairs a quadratic scan finds.
    #[test]
    fn overlapping_pairs_are_those_of_a_quadratic_scan() {
        let mut bits = crate::support::test_random::xorshift(0x853c_49e6_748f_ea9b);
        let mut next = move || (bits() % 1000) as f64 / 10.0;
        for count in [0usize, 1, 2, 5, 17, 300, 3000] {
            let boxes: Vec<BoundingBox> = (0..count)
                .map(|i| match i % 5 {
                    // The same box many times: centres cannot be split by position.
                    0 => BoundingBox::of_points(&[[1.0; 3], [2.0; 3]]),
                    // Unit cubes on a grid: neighbours touch along faces and corners.
                    1 => {
                        let c = [(i % 7) as f64, (i / 7 % 7) as f64, (i / 49 % 7) as f64];
                        BoundingBox::of_points(&[c, c.map(|x| x + 1.0)])
                    }
                    _ => {
                        let (p, q) = ([next(), next(), next()], [next(), next(), next()]);
                        BoundingBox::of_points(&[p, q.map(|x| x / 20.0 + p[0])])
                    }
                })
                .collect();
            let mut expected = Vec::new();
            for i in 0..count {
                for j in i + 1..count {
                    if boxes[i].overlaps(&boxes[j]) {
                        expected.push([i as u32, j as u32]);
                    }
                }
            }
            let items = boxes.iter().enumerate().map(|(i, b)| Item(i as u32, *b));
            let tree = BoxTree::new(items.collect());
            let mut found = tree.overlapping_pairs(|a, b| Some([a.0.min(b.0), a.0.max(b.0)]));
            found.sort_unstable();
            assert_eq!(found, expected, "{count} boxes");
        }
    }
}
