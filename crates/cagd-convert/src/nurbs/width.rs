//! [`Width`]: the number of working coordinates of a point as a type, so that the kernels of
//! the general route are compiled once per common width (2, 3, 4: plane and space,
//! polynomial or homogeneous) with fixed-length inner loops, and once for any width (the
//! rows of a surface). Beyond the seed: an implementation device only.

/// A point width known at compile time ([`Fixed`]) or at run time ([`Dynamic`]).
pub(crate) trait Width: Copy {
    /// The number of working coordinates.
    fn get(self) -> usize;
}

/// A width known at compile time.
#[derive(Clone, Copy)]
pub(crate) struct Fixed<const D: usize>;

impl<const D: usize> Width for Fixed<D> {
    #[inline(always)]
    fn get(self) -> usize {
        D
    }
}

/// A width known at run time.
#[derive(Clone, Copy)]
pub(crate) struct Dynamic(pub(crate) usize);

impl Width for Dynamic {
    #[inline(always)]
    fn get(self) -> usize {
        self.0
    }
}

/// Calls `$f` with the [`Width`] of `$pdim`: [`Fixed`] for 1 to 4, else [`Dynamic`].
macro_rules! with_width {
    ($pdim:expr, $f:ident ( $($arg:expr),* )) => {
        match $pdim {
            1 => $f($($arg,)* $crate::nurbs::width::Fixed::<1>),
            2 => $f($($arg,)* $crate::nurbs::width::Fixed::<2>),
            3 => $f($($arg,)* $crate::nurbs::width::Fixed::<3>),
            4 => $f($($arg,)* $crate::nurbs::width::Fixed::<4>),
            d => $f($($arg,)* $crate::nurbs::width::Dynamic(d)),
        }
    };
}
pub(crate) use with_width;
