//! Fuzzes the Voronoi diagram: any sites on a small grid (so duplicates, collinear and
//! cocircular sets are common), each at its own magnitude from 1e-300 to 1e300, build a diagram
//! or give a typed error; a built one answers nearest-site queries at every site with a site at
//! that very position, and clips to a box at any magnitude (whose area may under- or overflow)
//! with one cell per site, every corner finite.
#![no_main]

use halfwing::voronoi::{ClipPolygon, Voronoi};
use libfuzzer_sys::fuzz_target;

const SCALES: [f64; 7] = [1e-300, 1e-100, 1e-3, 1.0, 1e3, 1e100, 1e300];

fuzz_target!(|bytes: &[u8]| {
    let Some((&clip_magnitude, rest)) = bytes.split_first() else {
        return;
    };
    let sites: Vec<[f64; 2]> = rest
        .chunks_exact(3)
        .take(200)
        .map(|triple| {
            let scale = SCALES[usize::from(triple[2] % 7)];
            [f64::from(triple[0] % 32) * scale, f64::from(triple[1] % 32) * scale]
        })
        .collect();
    let Ok(diagram) = Voronoi::new(&sites) else {
        return;
    };
    for (i, &site) in sites.iter().enumerate() {
        let nearest = diagram
            .nearest_site(site, None)
            .expect("a finite query is answered")
            .expect("a diagram with sites has a nearest site");
        assert_eq!(sites[nearest.index()], site, "site {i}: nearest is {nearest}");
    }
    let scale = SCALES[usize::from(clip_magnitude % 7)];
    let clip = ClipPolygon::rectangle([-scale, -scale], [40.0 * scale, 40.0 * scale])
        .expect("a box at any magnitude is accepted");
    let cells = diagram.clip(&clip);
    assert_eq!(cells.n_cells(), sites.len());
    assert!(cells.positions().iter().flatten().all(|x| x.is_finite()));
});
