//! The OpenDRIVE import: the bytes as text (lossily decoded UTF-8), imported; an import never
//! panics, an error names the file and says why in one line, and a network that imports is
//! valid and answers finite surface points along every road. Structure comes from the seed
//! files (`fuzz/seeds/opendrive`).

#![no_main]

use libfuzzer_sys::fuzz_target;
use sim::road::opendrive::parse_str;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    match parse_str("f.xodr", &text) {
        Err(e) => {
            let message = e.to_string();
            assert!(message.starts_with("f.xodr"), "{message}");
            assert!(!message.contains('\n') || message.contains("XML"), "{message}");
        }
        Ok(imported) => {
            assert!(imported.network.validate().is_ok());
            for road in &imported.network.roads {
                let length = road.length();
                for i in 0..=8 {
                    let s = length * f64::from(i) / 8.0;
                    let p = road.surface_point(s, 1.0);
                    assert!(p.iter().all(|c| c.is_finite()), "road {} at s = {s}: {p:?}", road.id);
                }
            }
        }
    }
});
