//! Three-vectors over any [`Scalar`]; the note's vectors lie in the x-y plane with torques and
//! angular momenta along z, but the general identities of Appendix A hold in three dimensions and
//! are checked there.

use crate::scalar::Scalar;
use std::ops::{Add, Neg, Sub};

/// A vector (x, y, z).
#[derive(Clone, Debug, PartialEq)]
pub struct Vec3<T> {
    /// x component.
    pub x: T,
    /// y component.
    pub y: T,
    /// z component.
    pub z: T,
}

impl<T: Scalar> Vec3<T> {
    /// (x, y, z).
    pub fn new(x: T, y: T, z: T) -> Self {
        Vec3 { x, y, z }
    }
    /// A vector in the plane of the figure, (x, y, 0).
    pub fn planar(x: T, y: T) -> Self {
        Vec3 { x, y, z: T::int(0) }
    }
    /// z ẑ: how the note writes torques and angular momenta, "τ ẑ".
    pub fn along_z(z: T) -> Self {
        Vec3 {
            x: T::int(0),
            y: T::int(0),
            z,
        }
    }
    /// The zero vector.
    pub fn zero() -> Self {
        Self::along_z(T::int(0))
    }
    /// The cross product `self × o` (the note's ×, Milne's ∧).
    pub fn cross(&self, o: &Self) -> Self {
        let (a, b) = (self, o);
        Vec3 {
            x: a.y.clone() * b.z.clone() - a.z.clone() * b.y.clone(),
            y: a.z.clone() * b.x.clone() - a.x.clone() * b.z.clone(),
            z: a.x.clone() * b.y.clone() - a.y.clone() * b.x.clone(),
        }
    }
    /// The dot product.
    pub fn dot(&self, o: &Self) -> T {
        self.x.clone() * o.x.clone() + self.y.clone() * o.y.clone() + self.z.clone() * o.z.clone()
    }
    /// `k · self`.
    pub fn scale(&self, k: &T) -> Self {
        Vec3 {
            x: k.clone() * self.x.clone(),
            y: k.clone() * self.y.clone(),
            z: k.clone() * self.z.clone(),
        }
    }
    /// `self / k`.
    pub fn div(&self, k: &T) -> Self {
        Vec3 {
            x: self.x.clone() / k.clone(),
            y: self.y.clone() / k.clone(),
            z: self.z.clone() / k.clone(),
        }
    }
    /// The components, in order.
    pub fn components(&self) -> [T; 3] {
        [self.x.clone(), self.y.clone(), self.z.clone()]
    }
    /// `self + dself ε`, component by component.
    pub fn lift(&self, d: &Self) -> Vec3<T::Dual> {
        Vec3 {
            x: T::lift(self.x.clone(), d.x.clone()),
            y: T::lift(self.y.clone(), d.y.clone()),
            z: T::lift(self.z.clone(), d.z.clone()),
        }
    }
    /// The value of a lifted vector (its ε part dropped).
    pub fn value_of(d: &Vec3<T::Dual>) -> Self {
        Self::split(d).0
    }
    /// The derivative (ε part) of a lifted vector.
    pub fn derivative_of(d: &Vec3<T::Dual>) -> Self {
        Self::split(d).1
    }
    /// (value, derivative) of a lifted vector.
    pub fn split(d: &Vec3<T::Dual>) -> (Self, Self) {
        let (x, dx) = T::split(d.x.clone());
        let (y, dy) = T::split(d.y.clone());
        let (z, dz) = T::split(d.z.clone());
        (
            Vec3 { x, y, z },
            Vec3 {
                x: dx,
                y: dy,
                z: dz,
            },
        )
    }
    /// Embed a vector of constants (zero derivative) in the dual numbers.
    pub fn constant(&self) -> Vec3<T::Dual> {
        self.lift(&Self::zero())
    }
}

impl<T: Scalar> Add for Vec3<T> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Vec3 {
            x: self.x + o.x,
            y: self.y + o.y,
            z: self.z + o.z,
        }
    }
}

impl<T: Scalar> Sub for Vec3<T> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Vec3 {
            x: self.x - o.x,
            y: self.y - o.y,
            z: self.z - o.z,
        }
    }
}

impl<T: Scalar> Neg for Vec3<T> {
    type Output = Self;
    fn neg(self) -> Self {
        Vec3 {
            x: -self.x,
            y: -self.y,
            z: -self.z,
        }
    }
}

/// Sum of a sequence of vectors (zero when empty).
pub fn sum<T: Scalar>(it: impl IntoIterator<Item = Vec3<T>>) -> Vec3<T> {
    it.into_iter().fold(Vec3::zero(), |a, b| a + b)
}
