"""python -m cbfgen.emit.docs.workbench: write the workbench page."""

from . import main

raise SystemExit(main())
