//! Union–find (disjoint sets) with path halving: the connectivity of vertex links
//! (Def. 3.1.6), the orientation of a mesh, the classes of a gluing relation (Thm. 3.4.1) and
//! the components of isocurves and isosurfaces all use this one.
//!
//! `union(a, b)` links a's root under b's root, so the root of every class, and with it the
//! order of classes keyed by root, depends only on the sequence of unions.

/// Disjoint sets over `0..n`.
#[derive(Debug, Clone)]
pub struct UnionFind {
    parent: Vec<usize>,
}

impl UnionFind {
    /// `n` singletons.
    pub fn new(n: usize) -> Self {
        UnionFind {
            parent: (0..n).collect(),
        }
    }

    /// The root of x's class (path halving on the way).
    pub fn find(&mut self, mut x: usize) -> usize {
        while self.parent[x] != x {
            self.parent[x] = self.parent[self.parent[x]];
            x = self.parent[x];
        }
        x
    }

    /// Merge the classes of a and b (a's root goes under b's). True when they were apart.
    pub fn union(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return false;
        }
        self.parent[ra] = rb;
        true
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        self.parent.len()
    }

    /// No elements.
    pub fn is_empty(&self) -> bool {
        self.parent.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn classes_and_roots_follow_the_unions() {
        let mut u = UnionFind::new(6);
        assert!(u.union(0, 1));
        assert!(u.union(1, 2));
        assert!(!u.union(0, 2), "already one class");
        assert!(u.union(4, 5));
        // The root of {0, 1, 2} is 2 (each union puts a's root under b's).
        assert_eq!(u.find(0), 2);
        assert_eq!(u.find(1), 2);
        assert_eq!(u.find(3), 3);
        assert_eq!(u.find(4), 5);
        assert_ne!(u.find(0), u.find(4));
        assert_eq!(u.len(), 6);
        assert!(!u.is_empty() && UnionFind::new(0).is_empty());
    }
}
