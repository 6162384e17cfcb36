//! Chapter 04's fog settings: visibility falls from one to nothing, and
//! the opaque distance is where one 255th is left. (Here, beside the other
//! workspace tests, to save chapter 04 a test binary of its own.)

use fog::FogSettings;

#[test]
fn visibility_falls_from_one_to_nothing() {
    let fog = FogSettings::HAZE;
    assert_eq!(fog.visibility(0.0), 1.0);
    assert!(fog.visibility(100.0) > fog.visibility(1000.0));
    // At 1/density metres the exponent is 1 whatever the gradient: e⁻¹.
    let one_over_e = fog.visibility(1.0 / fog.density);
    assert!((one_over_e - (-1f32).exp()).abs() < 1e-6);
    assert_eq!(FogSettings::NONE.visibility(1e6), 1.0);
}

#[test]
fn the_opaque_distance_is_where_one_255th_is_left() {
    for fog in [FogSettings::HAZE, FogSettings::DUST_STORM] {
        let d = fog.opaque_distance();
        assert!((fog.visibility(d) - 1.0 / 255.0).abs() < 1e-5, "{fog:?}");
    }
    assert!(FogSettings::NONE.opaque_distance().is_infinite());
    assert!((FogSettings::DUST_STORM.opaque_distance() - 588.0).abs() < 1.0);
}
