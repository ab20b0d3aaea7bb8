//! 64-bit FNV-1a (Fowler, Noll & Vo): a small, portable, non-cryptographic hash for
//! fingerprints and cache keys whose value must be the same on every machine and run.

/// The running hash; feed bytes ([`Fnv1a::bytes`]) or text (`write!`, via [`std::fmt::Write`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fnv1a(pub u64);

impl Default for Fnv1a {
    fn default() -> Self {
        Fnv1a(0xcbf2_9ce4_8422_2325)
    }
}

impl Fnv1a {
    /// Folds `bytes` into the hash.
    pub fn bytes(&mut self, bytes: &[u8]) -> &mut Self {
        for &b in bytes {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
        }
        self
    }
}

impl std::fmt::Write for Fnv1a {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        self.bytes(s.as_bytes());
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_the_published_test_vectors() {
        // FNV-1a 64-bit reference values (the FNV authors' test suite)
        assert_eq!(Fnv1a::default().0, 0xcbf2_9ce4_8422_2325);
        assert_eq!(Fnv1a::default().bytes(b"a").0, 0xaf63_dc4c_8601_ec8c);
        assert_eq!(Fnv1a::default().bytes(b"foobar").0, 0x8594_4171_f739_67e8);
        // text and bytes agree
        let mut t = Fnv1a::default();
        std::fmt::Write::write_str(&mut t, "foobar").unwrap();
        assert_eq!(t, *Fnv1a::default().bytes(b"foobar"));
    }
}
