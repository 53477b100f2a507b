//! The little-endian CDR encoding of ROS 2 messages (XCDR1, as rmw writes
//! them): a 4-byte encapsulation header, then each field aligned to its
//! size relative to the end of the header.

pub(crate) struct Cdr {
    buf: Vec<u8>,
}

impl Cdr {
    pub(crate) fn new() -> Cdr {
        Cdr {
            buf: vec![0x00, 0x01, 0x00, 0x00],
        }
    }

    fn align(&mut self, n: usize) {
        while (self.buf.len() - 4) % n != 0 {
            self.buf.push(0);
        }
    }

    pub(crate) fn u8(&mut self, v: u8) {
        self.buf.push(v);
    }

    pub(crate) fn bool(&mut self, v: bool) {
        self.buf.push(u8::from(v));
    }

    pub(crate) fn u32(&mut self, v: u32) {
        self.align(4);
        self.buf.extend_from_slice(&v.to_le_bytes());
    }

    pub(crate) fn i32(&mut self, v: i32) {
        self.align(4);
        self.buf.extend_from_slice(&v.to_le_bytes());
    }

    pub(crate) fn f32(&mut self, v: f32) {
        self.align(4);
        self.buf.extend_from_slice(&v.to_le_bytes());
    }

    pub(crate) fn f64(&mut self, v: f64) {
        self.align(8);
        self.buf.extend_from_slice(&v.to_le_bytes());
    }

    /// A string: its length with the terminating NUL, the bytes, the NUL.
    pub(crate) fn string(&mut self, s: &str) {
        self.u32(s.len() as u32 + 1);
        self.buf.extend_from_slice(s.as_bytes());
        self.buf.push(0);
    }

    /// A sequence of bytes: its length, then the bytes.
    pub(crate) fn bytes(&mut self, b: &[u8]) {
        self.u32(b.len() as u32);
        self.buf.extend_from_slice(b);
    }

    /// `builtin_interfaces/Time` (or `Duration`) of `ns` nanoseconds.
    pub(crate) fn time(&mut self, ns: u64) {
        self.i32((ns / 1_000_000_000) as i32);
        self.u32((ns % 1_000_000_000) as u32);
    }

    /// `std_msgs/Header`.
    pub(crate) fn header(&mut self, stamp_ns: u64, frame_id: &str) {
        self.time(stamp_ns);
        self.string(frame_id);
    }

    pub(crate) fn into_bytes(self) -> Vec<u8> {
        self.buf
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_align_after_the_header() {
        let mut c = Cdr::new();
        c.u8(1);
        c.f64(2.0);
        c.string("ab");
        let b = c.into_bytes();
        assert_eq!(&b[..5], &[0, 1, 0, 0, 1]);
        // The float64 starts 8 bytes after the header.
        assert_eq!(&b[12..20], &2.0f64.to_le_bytes());
        assert_eq!(&b[20..27], &[3, 0, 0, 0, b'a', b'b', 0]);
    }
}
