fn main() -> std::process::ExitCode {
    common::run::<instancing::InstancingChapter>()
}
