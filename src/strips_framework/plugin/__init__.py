"""The plugin machinery: the hook specifications, the registries filled from them, the
builtin implementations (registered like an outside plugin), capabilities and the TOML
config that picks implementations by name."""
