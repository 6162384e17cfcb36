fn main() -> std::process::ExitCode {
    common::run::<water::WaterChapter>()
}
