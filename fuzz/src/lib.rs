//! Shared decoding for the fuzz targets: bytes to f64 sequences that mix raw bit patterns
//! (every exponent, NaN, infinities, subnormals) with small round numbers and repeats, so that
//! ties, plateaus and ordinary magnitudes are as likely as the extremes.

/// Decodes `bytes` into values: each starts with a tag byte choosing how the next bytes are
/// read.
pub fn values(bytes: &[u8]) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let tag = bytes[i];
        i += 1;
        let v = match tag % 5 {
            // Raw bits: any f64 at all.
            0 => {
                let mut b = [0u8; 8];
                let n = (bytes.len() - i).min(8);
                b[..n].copy_from_slice(&bytes[i..i + n]);
                i += n;
                f64::from_le_bytes(b)
            }
            // Small integers and halves: ties and equal extremes.
            1 => f64::from(tag as i8 >> 1) * 0.5,
            // A repeat of the previous value (plateaus).
            2 => out.last().copied().unwrap_or(0.0),
            // A 16-bit fixed-point number in [-128, 128).
            3 => {
                let mut b = [0u8; 2];
                let n = (bytes.len() - i).min(2);
                b[..n].copy_from_slice(&bytes[i..i + n]);
                i += n;
                f64::from(i16::from_le_bytes(b)) / 256.0
            }
            // A power of ten from 1e-320 to 1e308, with the sign from the tag.
            _ => {
                let e = bytes.get(i).copied().unwrap_or(0);
                i += 1;
                let x = 10f64.powi(i32::from(e) * 628 / 255 - 320);
                if tag & 0x80 != 0 {
                    -x
                } else {
                    x
                }
            }
        };
        out.push(v);
    }
    out
}
