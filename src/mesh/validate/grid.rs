//! The broad phase of Def. 3.1.3(ii): a uniform grid over the triangles' boxes that answers
//! "which boxes meet this box" with exactly the set an R*-tree's
//! `locate_in_envelope_intersecting` gives (the same closed-box test decides each candidate;
//! the grid only chooses which boxes to test), in less time for the near-uniform triangles of
//! a scanned or modelled surface. Ill-conditioned inputs (boxes of very different sizes, many
//! boxes in one cell) are left to the R*-tree, which is then the same answer at its own speed.
//!
//! Why no box is missed: a coordinate's cell index is floor((x − lo)·inv) clamped, computed
//! with the same rounded operations for the stored boxes and for the query; each step is
//! monotone, so two boxes that overlap on an axis get overlapping index ranges on it, and
//! hence share a cell.

use super::fans::FaceBox;
use rstar::{Envelope, RTree, AABB};

/// Boxes spanning more cells than this are kept in a list tested by every query.
const MAX_SPAN: usize = 64;
/// More such boxes than this: the grid is not a good index for the input.
const MAX_BIG: usize = 32;
/// More boxes than this in one bucket: likewise.
const MAX_OCCUPANCY: usize = 256;
/// Cell edge over the median box extent (koala: 2 tested fewer boxes than 1; at 4 some buckets
/// of its dense parts exceed MAX_OCCUPANCY).
const CELL_PER_EXTENT: f64 = 2.0;

/// The candidate search over a set of boxes: a grid when it suits the input, else an R*-tree.
pub(super) enum BoxIndex {
    Grid(BoxGrid),
    Tree(RTree<FaceBox>),
}

impl BoxIndex {
    pub(super) fn new(mut items: Vec<FaceBox>) -> Self {
        match BoxGrid::build(&mut items) {
            Some(mut g) => {
                g.items = items;
                BoxIndex::Grid(g)
            }
            None => BoxIndex::Tree(RTree::bulk_load(items)),
        }
    }

    /// Calls `f` for every stored box of a face numbered above `above` that meets `env`
    /// (closed boxes), each once.
    pub(super) fn each_intersecting_above(
        &self,
        env: &AABB<[f64; 3]>,
        above: u32,
        mut f: impl FnMut(&FaceBox),
    ) {
        match self {
            BoxIndex::Tree(t) => t
                .locate_in_envelope_intersecting(env)
                .filter(|b| b.face > above)
                .for_each(f),
            BoxIndex::Grid(g) => g.each_intersecting_above(env, above, &mut f),
        }
    }
}

pub(super) struct BoxGrid {
    lo: [f64; 3],
    inv: [f64; 3],
    dims: [usize; 3],
    /// log2 of the number of buckets; cell (x, y, z) is in bucket `bucket(x, y, z)`.
    bits: u32,
    /// Bucket k holds the entries `start[k]..start[k + 1]` of `cells`: one per stored item of
    /// each cell hashed to k.
    start: Vec<u32>,
    cells: Vec<Entry>,
    /// Items spanning more than MAX_SPAN cells.
    big: Vec<u32>,
    items: Vec<FaceBox>,
}

impl BoxGrid {
    /// The grid for `items` (without the items, which the caller moves in), or None when the
    /// input does not suit a uniform grid. The items are reordered along a Z-order curve of
    /// their first cells, so that the boxes a query tests lie close together in memory.
    fn build(items: &mut [FaceBox]) -> Option<Self> {
        let n = items.len();
        if n == 0 || n >= (1 << 29) / MAX_SPAN {
            return None;
        }
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        let mut ext: Vec<f64> = Vec::with_capacity(n);
        for it in items.iter() {
            let (a, b) = (it.env.lower(), it.env.upper());
            let mut e = 0.0f64;
            for d in 0..3 {
                lo[d] = lo[d].min(a[d]);
                hi[d] = hi[d].max(b[d]);
                e = e.max(b[d] - a[d]);
            }
            ext.push(e);
        }
        if !(lo.iter().chain(&hi).all(|x| x.is_finite())) {
            return None;
        }
        // Cell edge: the median box extent (a typical box spans about two cells an axis), the
        // cells of a surface being few of the whole lattice: only occupied cells are stored,
        // hashed into buckets.
        let mid = n / 2;
        let (_, &mut median, _) = ext.select_nth_unstable_by(mid, f64::total_cmp);
        let span = [hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]];
        let mut h = median * CELL_PER_EXTENT;
        if !(h.is_finite() && h > 0.0) {
            return None;
        }
        let most = (1u64 << 20) as f64;
        let widest = span[0].max(span[1]).max(span[2]);
        if widest / h > most {
            h = widest / most;
        }
        let dims = span.map(|s| ((s / h).ceil().max(1.0) as usize).min(1 << 20));
        let inv = [0, 1, 2].map(|d| {
            if span[d] > 0.0 {
                dims[d] as f64 / span[d]
            } else {
                0.0
            }
        });
        let mut g = BoxGrid {
            lo,
            inv,
            dims,
            bits: 0,
            start: Vec::new(),
            cells: Vec::new(),
            big: Vec::new(),
            items: Vec::new(),
        };
        items.sort_by_cached_key(|it| {
            let (a, _) = g.range(&it.env);
            morton(a)
        });
        let mut ranges = Vec::with_capacity(n);
        let mut entries = 0usize;
        for (i, it) in items.iter().enumerate() {
            let (a, b) = g.range(&it.env);
            let cells = (b[0] - a[0] + 1) * (b[1] - a[1] + 1) * (b[2] - a[2] + 1);
            if cells > MAX_SPAN {
                g.big.push(i as u32);
                if g.big.len() > MAX_BIG {
                    return None;
                }
                ranges.push(None);
                continue;
            }
            entries += cells;
            ranges.push(Some((a, b)));
        }
        g.bits = (2 * entries).max(64).next_power_of_two().trailing_zeros();
        let nb = 1usize << g.bits;
        // Counting sort of (cell, item) by bucket.
        let mut count = vec![0u32; nb + 1];
        for (a, b) in ranges.iter().flatten() {
            g.for_buckets(*a, *b, |k| count[k] += 1);
        }
        if count.iter().any(|&c| c as usize > MAX_OCCUPANCY) {
            return None;
        }
        let mut total = 0u32;
        for c in count.iter_mut() {
            let k = *c;
            *c = total;
            total += k;
        }
        let empty = Entry {
            cell: u64::MAX,
            face: 0,
            item: 0,
        };
        g.cells = vec![empty; total as usize];
        let mut fill = count.clone();
        for (i, r) in ranges.iter().enumerate() {
            if let Some((a, b)) = r {
                let (cells, bits, dims) = (&mut g.cells, g.bits, g.dims);
                for_cells(dims, *a, *b, |x, y, z| {
                    let cell = key(x, y, z);
                    let k = bucket(bits, cell);
                    let flags = u32::from(x == a[0])
                        | u32::from(y == a[1]) << 1
                        | u32::from(z == a[2]) << 2;
                    cells[fill[k] as usize] = Entry {
                        cell,
                        face: items[i].face,
                        item: (i as u32) << 3 | flags,
                    };
                    fill[k] += 1;
                });
            }
        }
        g.start = count;
        Some(g)
    }

    fn index(&self, d: usize, x: f64) -> usize {
        let t = ((x - self.lo[d]) * self.inv[d]).floor();
        t.max(0.0).min((self.dims[d] - 1) as f64) as usize
    }

    fn range(&self, env: &AABB<[f64; 3]>) -> ([usize; 3], [usize; 3]) {
        let (a, b) = (env.lower(), env.upper());
        (
            [0, 1, 2].map(|d| self.index(d, a[d])),
            [0, 1, 2].map(|d| self.index(d, b[d])),
        )
    }

    fn for_buckets(&self, a: [usize; 3], b: [usize; 3], mut f: impl FnMut(usize)) {
        let bits = self.bits;
        for_cells(self.dims, a, b, |x, y, z| f(bucket(bits, key(x, y, z))))
    }

    fn each_intersecting_above(
        &self,
        env: &AABB<[f64; 3]>,
        above: u32,
        f: &mut impl FnMut(&FaceBox),
    ) {
        let (a, b) = self.range(env);
        let cells: u128 = (0..3).map(|d| (b[d] - a[d] + 1) as u128).product();
        if cells > self.items.len() as u128 {
            // A query spanning more cells than there are boxes (a huge triangle among tiny
            // ones): testing every box is cheaper and bounded, where the walk over its cells
            // took 2 s on a fuzzed 20-face mesh. The same closed-box test decides.
            for it in &self.items {
                if it.face > above && it.env.intersects(env) {
                    f(it);
                }
            }
            return;
        }
        for &i in &self.big {
            let it = &self.items[i as usize];
            if it.face > above && it.env.intersects(env) {
                f(it);
            }
        }
        for_cells(self.dims, a, b, |x, y, z| {
            let cell = key(x, y, z);
            let k = bucket(self.bits, cell);
            // The axes on which this cell is the query's first: there, any item of the cell
            // has its first shared cell here; elsewhere only an item starting here does.
            let at_start =
                u32::from(x == a[0]) | u32::from(y == a[1]) << 1 | u32::from(z == a[2]) << 2;
            let (s, e) = (self.start[k] as usize, self.start[k + 1] as usize);
            for en in &self.cells[s..e] {
                // Report from the first cell shared by the item's and the query's ranges
                // only; skip the entries of other cells hashed to the same bucket.
                if en.cell != cell || en.face <= above || (en.item | at_start) & 7 != 7 {
                    continue;
                }
                let it = &self.items[(en.item >> 3) as usize];
                if it.env.intersects(env) {
                    f(it);
                }
            }
        });
    }
}

/// An item stored in a cell.
#[derive(Clone, Copy)]
struct Entry {
    /// The cell, packed by [`key`].
    cell: u64,
    /// The item's face (tested before the item is looked up).
    face: u32,
    /// (index into `items`) << 3 | a bit per axis d set when the cell is the item's first on
    /// that axis.
    item: u32,
}

/// The Z-order (Morton) index of a cell: the bits of x, y, z interleaved.
fn morton(c: [usize; 3]) -> u64 {
    let spread = |v: usize| {
        let mut x = v as u64 & 0x1f_ffff;
        x = (x | x << 32) & 0x1f_0000_0000_ffff;
        x = (x | x << 16) & 0x1f_0000_ff00_00ff;
        x = (x | x << 8) & 0x100f_00f0_0f00_f00f;
        x = (x | x << 4) & 0x10c3_0c30_c30c_30c3;
        (x | x << 2) & 0x1249_2492_4924_9249
    };
    spread(c[0]) | spread(c[1]) << 1 | spread(c[2]) << 2
}

/// Cell (x, y, z) (each < 2^21) packed into one word.
fn key(x: usize, y: usize, z: usize) -> u64 {
    (x as u64) | ((y as u64) << 21) | ((z as u64) << 42)
}

/// The bucket of a cell: a multiplicative hash of its key.
fn bucket(bits: u32, key: u64) -> usize {
    (key.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> (64 - bits)) as usize
}

fn for_cells(
    dims: [usize; 3],
    a: [usize; 3],
    b: [usize; 3],
    mut f: impl FnMut(usize, usize, usize),
) {
    debug_assert!(b[0] < dims[0] && b[1] < dims[1] && b[2] < dims[2]);
    for x in a[0]..=b[0] {
        for y in a[1]..=b[1] {
            for z in a[2]..=b[2] {
                f(x, y, z);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    fn boxes(seed: u64, n: usize, size: f64) -> Vec<FaceBox> {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        (0..n)
            .map(|i| {
                let a: [f64; 3] = [0, 1, 2].map(|_| rng.gen_range(-1.0..1.0));
                let e: [f64; 3] = [0, 1, 2].map(|_| rng.gen_range(0.0..size));
                // Some boxes touching others exactly, some flat.
                let b = if i % 7 == 0 {
                    a
                } else {
                    [a[0] + e[0], a[1] + e[1], a[2] + e[2]]
                };
                FaceBox {
                    face: i as u32,
                    env: AABB::from_corners(a, b),
                }
            })
            .collect()
    }

    /// D3.1.3(ii)'s broad phase: the grid reports exactly the boxes the R*-tree reports, each
    /// once, for boxes of one size, of mixed sizes, with a few huge boxes, and for queries
    /// that are the stored boxes themselves (touching boundaries included); an input with too
    /// many huge boxes falls back to the tree.
    #[test]
    fn d3_1_3_ii_grid_finds_the_r_tree_candidates() {
        let mut inputs = vec![boxes(1, 3000, 0.05), boxes(2, 2000, 0.3)];
        let mut with_big = boxes(3, 2000, 0.04);
        for k in 0..5 {
            with_big[k * 100].env = AABB::from_corners([-1.0; 3], [1.0 - k as f64 * 0.1; 3]);
        }
        inputs.push(with_big);
        let mut grid_used = 0;
        for items in inputs {
            let tree = RTree::bulk_load(items.clone());
            let index = BoxIndex::new(items.clone());
            grid_used += usize::from(matches!(index, BoxIndex::Grid(_)));
            let mut queries: Vec<AABB<[f64; 3]>> = items.iter().map(|b| b.env).collect();
            queries.push(AABB::from_corners([-2.0; 3], [2.0; 3]));
            queries.push(AABB::from_corners([5.0; 3], [6.0; 3]));
            for q in &queries {
                let mut want: Vec<u32> = tree
                    .locate_in_envelope_intersecting(q)
                    .map(|b| b.face)
                    .collect();
                let mut got = Vec::new();
                index.each_intersecting_above(q, 0, |b| got.push(b.face));
                want.retain(|&f| f > 0);
                want.sort_unstable();
                got.sort_unstable();
                assert_eq!(got, want);
            }
        }
        assert_eq!(grid_used, 3);
        let mut many_big = boxes(4, 500, 0.01);
        for b in many_big.iter_mut().take(40) {
            b.env = AABB::from_corners([-1.0; 3], [1.0; 3]);
        }
        assert!(matches!(BoxIndex::new(many_big), BoxIndex::Tree(_)));
    }
}
