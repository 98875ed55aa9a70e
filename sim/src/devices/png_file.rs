//! PNG files of camera images and displays: what `wb_camera_save_image`,
//! `wb_display_image_save` and `wb_display_image_load` read and write.

use std::fs::File;
use std::io::{BufReader, BufWriter};
use std::path::Path;

use super::display::{DisplayImage, MAX_SIDE, PixelFormat};

/// Why an image file could not be written or read.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ImageFileError {
    /// The file could not be created, opened, written or read.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// What went wrong.
        source: std::io::Error,
    },
    /// The PNG encoder or decoder failed (a broken file, an unsupported PNG).
    #[error("{path}: {message}")]
    Png {
        /// The file.
        path: String,
        /// What went wrong.
        message: String,
    },
    /// Only PNG files are written and read here.
    #[error("{0}: only .png files are supported")]
    NotPng(String),
}

fn is_png(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("png"))
}

/// Writes `image` (ARGB) as an RGBA PNG at `path` (whose extension must be `.png`).
///
/// # Errors
/// [`ImageFileError`].
pub fn save_png(path: &Path, image: &DisplayImage) -> Result<(), ImageFileError> {
    let name = path.display().to_string();
    if !is_png(path) {
        return Err(ImageFileError::NotPng(name));
    }
    let io = |source| ImageFileError::Io {
        path: name.clone(),
        source,
    };
    let png = |e: png::EncodingError| ImageFileError::Png {
        path: name.clone(),
        message: e.to_string(),
    };
    let file = File::create(path).map_err(io)?;
    let mut encoder = png::Encoder::new(BufWriter::new(file), image.width, image.height);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(png)?;
    writer.write_image_data(&image.rgba()).map_err(png)?;
    writer.finish().map_err(png)
}

/// Reads the 8-bit RGB or RGBA PNG at `path` (its extension must be `.png`).
///
/// # Errors
/// [`ImageFileError`], also for a PNG of another colour type or bit depth, or a side above
/// 4096 px.
pub fn load_png(path: &Path) -> Result<DisplayImage, ImageFileError> {
    let name = path.display().to_string();
    if !is_png(path) {
        return Err(ImageFileError::NotPng(name));
    }
    let file = File::open(path).map_err(|source| ImageFileError::Io {
        path: name.clone(),
        source,
    })?;
    let fail = |message: String| ImageFileError::Png {
        path: name.clone(),
        message,
    };
    let mut reader = png::Decoder::new(BufReader::new(file))
        .read_info()
        .map_err(|e| fail(e.to_string()))?;
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| fail("image too large".to_string()))?;
    let info = reader.info();
    let (width, height) = (info.width, info.height);
    if width > MAX_SIDE || height > MAX_SIDE {
        return Err(fail(format!(
            "{width} x {height} px: at most 4096 px a side"
        )));
    }
    let mut data = vec![0; size];
    let frame = reader
        .next_frame(&mut data)
        .map_err(|e| fail(e.to_string()))?;
    let format = match (frame.color_type, frame.bit_depth) {
        (png::ColorType::Rgb, png::BitDepth::Eight) => PixelFormat::Rgb,
        (png::ColorType::Rgba, png::BitDepth::Eight) => PixelFormat::Rgba,
        (c, d) => return Err(fail(format!("{c:?} {d:?}: only 8-bit RGB or RGBA"))),
    };
    let bytes = data.get(..frame.buffer_size()).unwrap_or(&[]);
    DisplayImage::from_bytes(width, height, bytes, format)
        .ok_or_else(|| fail("truncated image data".to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_saved_image_loads_back_the_same() {
        let dir = std::env::temp_dir().join(format!("sim-png-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("frame.png");
        let image =
            DisplayImage::from_bytes(2, 1, &[10, 20, 30, 255, 40, 50, 60, 128], PixelFormat::Rgba)
                .unwrap();
        save_png(&path, &image).unwrap();
        assert_eq!(load_png(&path).unwrap(), image);
        assert!(matches!(
            save_png(&dir.join("frame.jpg"), &image),
            Err(ImageFileError::NotPng(_))
        ));
        assert!(matches!(
            load_png(&dir.join("missing.png")),
            Err(ImageFileError::Io { .. })
        ));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
