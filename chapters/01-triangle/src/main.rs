fn main() -> std::process::ExitCode {
    common::run::<triangle::Triangle>()
}
