"""The loader's passes, in the order they run (pipeline.check_order proves each reads only what a
pass before it produced). A new rule is a new module here and a line in PASSES."""

from __future__ import annotations

from ..pipeline import Pass
from .arg_checksums import ARG_CHECKSUM_FIELDS, ARG_CHECKSUMS, NAMED_COVERAGE_USERS
from .availability import AVAILABILITY, MACHINE_COVERAGE
from .bindings import CAPABILITIES, FORMER_NAMES, NAMES
from .checks import CHECK_PARAMS, CHECKS
from .checksums import CHECKSUM_DEFS, CHECKSUMS, COVERAGES
from .clauses import CLAUSES
from .commands import COMMAND_TABLE, COMMANDS
from .cut import CUT
from .deprecations import DEPRECATIONS
from .fill_order import FILL_ORDER
from .header_coverages import HEADER_COVERAGE_FIELDS, HEADER_COVERAGES
from .headers import HEADER_LAYOUTS, HEADERS
from .judged import HEADER_CHECKSUM_FIELDS, RECORD_CHECKSUM_CHECKS
from .limits import LIMITS, PADDING
from .machine import DECISIONS, MACHINE, MACHINE_LIMITS
from .notes import NOTES
from .numbers import NUMBERS
from .profiles import PROFILE_REFS, PROFILES
from .prose import PROSE
from .record import RECORD, RECORD_ROLES_PASS
from .repeat import REPEAT, REPEAT_GROUPS
from .roles import ROLES
from .targets import CHECK_TARGETS
from .types import TYPES_PASS
from .versions import VERSION_REFS, VERSIONS

PASSES: tuple[Pass, ...] = (
    NUMBERS, PADDING, TYPES_PASS, VERSIONS, VERSION_REFS, HEADERS, HEADER_LAYOUTS, RECORD, RECORD_ROLES_PASS, LIMITS,
    COMMANDS, COMMAND_TABLE, REPEAT_GROUPS, CUT, ROLES,
    CHECKSUMS, COVERAGES, CHECKSUM_DEFS, PROFILES, PROFILE_REFS, DECISIONS, MACHINE, MACHINE_LIMITS,
    CHECKS, CHECK_PARAMS, CHECK_TARGETS,
    ARG_CHECKSUMS, HEADER_COVERAGES, NAMED_COVERAGE_USERS, ARG_CHECKSUM_FIELDS, HEADER_COVERAGE_FIELDS,
    HEADER_CHECKSUM_FIELDS, RECORD_CHECKSUM_CHECKS, FILL_ORDER,
    DEPRECATIONS, AVAILABILITY, MACHINE_COVERAGE, CAPABILITIES, NAMES, FORMER_NAMES, REPEAT, CLAUSES, NOTES,
    PROSE,
)
