"""The ``ppm`` console script: the crate's command line (cli::main_from) from the extension."""

import sys


def main() -> None:
    from . import _native

    sys.exit(_native.ppm_main(["ppm", *sys.argv[1:]]))


if __name__ == "__main__":
    main()
