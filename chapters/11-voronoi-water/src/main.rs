fn main() -> std::process::ExitCode {
    common::run::<voronoi_water::VoronoiWaterChapter>()
}
