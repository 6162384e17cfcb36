fn main() -> std::process::ExitCode {
    common::run::<terrain::TerrainChapter>()
}
