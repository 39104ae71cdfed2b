//! Shell completions and the man page, both generated from the clap definitions of
//! `args.rs`, so they always list the options the program really takes.

/// The completion script for `shell`, to be sourced by it.
pub fn completions(shell: clap_complete::Shell) -> String {
    let mut cmd = completable();
    let mut out = Vec::new();
    clap_complete::generate(shell, &mut cmd, "groovelab", &mut out);
    String::from_utf8(out).expect("clap_complete writes UTF-8")
}

/// The command line as the completion scripts offer it: clap_complete offers hidden
/// options too (`presets --<TAB>` offered the 31 options it refuses, which
/// `args::command` hides from its help), so here the global options are the app's
/// own, and each command gets as options of its own those it takes, their conflicts
/// kept where the other option is taken too.
fn completable() -> clap::Command {
    use clap::CommandFactory;
    let parsed = super::args::command();
    let top = super::args::Cli::command();
    let globals: Vec<&clap::Arg> = top.get_arguments().filter(|a| a.is_global_set()).collect();
    let mut cmd = top.clone().mut_args(|a| a.global(false));
    for sub in parsed.get_subcommands() {
        // What a command does not take it holds as a hidden copy (`args::command`).
        let takes = |id: &clap::Id| {
            !sub.get_arguments()
                .any(|a| a.is_hide_set() && a.get_id() == id)
        };
        let own: Vec<clap::Arg> = globals
            .iter()
            .filter(|a| takes(a.get_id()))
            .map(|a| {
                let kept: Vec<clap::Id> = top
                    .get_arg_conflicts_with(a)
                    .into_iter()
                    .map(|c| c.get_id().clone())
                    .filter(|id| takes(id))
                    .collect();
                (*a).clone()
                    .global(false)
                    .conflicts_with(clap::builder::Resettable::<clap::Id>::Reset)
                    .conflicts_with_all(kept)
            })
            .collect();
        cmd = cmd.mut_subcommand(sub.get_name(), |s| s.args(own));
    }
    cmd
}

/// The man page groovelab(1), in roff: name, synopsis, description and the global
/// options as clap_mangen makes them, then one section per command with its own
/// synopsis and options (the page is one file: no groovelab-COMMAND(1) pages to refer to).
pub fn manpage() -> String {
    let cmd = super::args::command();
    let man = clap_mangen::Man::new(cmd.clone());
    let mut page = String::new();
    for part in [
        clap_mangen::Man::render_title,
        clap_mangen::Man::render_name_section,
        clap_mangen::Man::render_synopsis_section,
        clap_mangen::Man::render_description_section,
        clap_mangen::Man::render_options_section,
    ] {
        page += &render(|w| part(&man, w));
    }
    for sub in cmd.get_subcommands() {
        let name = format!("groovelab {}", sub.get_name());
        let man = clap_mangen::Man::new(sub.clone().bin_name(&name));
        page += &format!(".SH \"COMMAND: {}\"\n", name.to_uppercase());
        let about = sub.get_about().map(|a| a.to_string()).unwrap_or_default();
        page += &format!(".PP\n{}\n", roff_text(&about));
        let synopsis = render(|w| man.render_synopsis_section(w));
        page += &synopsis.replacen(".SH SYNOPSIS\n", ".SS Synopsis\n", 1);
        let options = render(|w| man.render_options_section(w));
        page += &options.replacen(".SH OPTIONS\n", ".SS Options\n", 1);
    }
    page += &render(|w| man.render_version_section(w));
    page
}

/// What a clap_mangen writer produced, as text.
fn render(write: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>) -> String {
    let mut out = Vec::new();
    write(&mut out).expect("writing to memory cannot fail");
    String::from_utf8(out).expect("clap_mangen writes UTF-8")
}

/// A line of plain text made safe for roff: a leading `.` or `'` would be a request,
/// and `\` starts an escape.
fn roff_text(text: &str) -> String {
    let text = text.replace('\\', "\\e");
    if text.starts_with(['.', '\'']) {
        format!("\\&{text}")
    } else {
        text
    }
}
