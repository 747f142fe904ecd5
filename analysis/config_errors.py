"""A config that breaks its schema, told in one line with the key's path, as `cellsim` tells a bad case:
"base.cell: unknown key 'turgor_kPA'; did you mean 'turgor_kPa'?". Snakemake's own `validate` then sets the
schema's defaults; it is called only on a config that passed here, so its long dump is never shown."""
import difflib
import pathlib

import jsonschema
import yaml


def load_yaml(uri):
    with open(uri.removeprefix("file://")) as handle:
        return yaml.safe_load(handle)


def key_path(error):
    return ".".join(str(part) for part in error.absolute_path) or "the config"


def nearest(word, known):
    """The known key closest to a misspelt one, ignoring case first (turgor_kPA -> turgor_kPa)."""
    by_case = [key for key in known if key.lower() == word.lower()]
    close = by_case or difflib.get_close_matches(word, known, n=1, cutoff=0.6)
    return close[0] if close else None


def unknown_keys_message(error):
    known = sorted(error.schema.get("properties", {}))
    extra = sorted(key for key in error.instance if key not in known)
    where = key_path(error)
    if not extra:  # additionalProperties given as a schema: the value broke it, not the key
        return f"{where}: {error.message}"
    hint = nearest(extra[0], known)
    known_text = f"did you mean '{hint}'?" if hint else f"known keys: {', '.join(known)}"
    return f"{where}: unknown key '{extra[0]}'; {known_text}"


def problem(config, schema_path):
    """One line naming the first key that breaks the schema (a YAML file, which may $ref files beside it), or
    None."""
    path = pathlib.Path(schema_path).resolve()
    schema = load_yaml(str(path))
    resolver = jsonschema.RefResolver(path.as_uri(), schema, handlers={"file": load_yaml})
    validator = jsonschema.validators.validator_for(schema)(schema, resolver=resolver)
    error = jsonschema.exceptions.best_match(validator.iter_errors(config))
    if error is None:
        return None
    if error.validator == "additionalProperties" and isinstance(error.instance, dict):
        return unknown_keys_message(error)
    message = " ".join(error.message.split())
    if len(message) > 200:  # a oneOf's message repeats the whole value
        message = message[:197] + "..."
    return f"{key_path(error)}: {message}"
