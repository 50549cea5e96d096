//! Fuzzes the Voronoi diagram: any sites on a small grid (so duplicates, collinear and
//! cocircular sets are common) at one magnitude per input, from 1e-300 to 1e300, build a
//! diagram or give a typed error; a built one answers nearest-site queries at every site with a
//! site at that very position, and clips to its box with one cell per site, every corner finite.
//!
//! Sites of very different magnitudes in one input are left out: there, nearest-site queries
//! are still wrong (sites (1.5e101, 0), (0, 0), (2e-100, 0): the query at the third returns
//! the second, the squared distances underflowing), a known open defect; mix the scales here once
//! it is fixed.
#![no_main]

use halfwing::voronoi::{ClipPolygon, Voronoi};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let Some((&magnitude, rest)) = bytes.split_first() else {
        return;
    };
    let scale = [1e-300, 1e-100, 1e-3, 1.0, 1e3, 1e100, 1e300][usize::from(magnitude % 7)];
    let sites: Vec<[f64; 2]> = rest
        .chunks_exact(2)
        .take(200)
        .map(|pair| [f64::from(pair[0] % 32) * scale, f64::from(pair[1] % 32) * scale])
        .collect();
    let Ok(diagram) = Voronoi::new(&sites) else {
        return;
    };
    for (i, &site) in sites.iter().enumerate() {
        let nearest = diagram
            .nearest_site(site, None)
            .expect("a finite query is answered")
            .expect("a diagram with sites has a nearest site");
        assert_eq!(sites[nearest as usize], site, "site {i}: nearest is {nearest}");
    }
    // At 1e±300 the box's area under- or overflows and the rectangle is refused as "zero area",
    // the same known defect: clip where it is accepted.
    let Ok(clip) = ClipPolygon::rectangle([-scale, -scale], [40.0 * scale, 40.0 * scale]) else {
        assert!(scale != 1.0, "the unit-scale box is accepted");
        return;
    };
    let cells = diagram.clip(&clip);
    assert_eq!(cells.n_cells(), sites.len());
    assert!(cells.positions().iter().flatten().all(|x| x.is_finite()));
});
