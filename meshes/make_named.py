"""Write the named meshes (``meshes.named.RECIPES``) as ``.vtu`` files here.

Run ``python -m pocket.meshes.make_named`` after changing a recipe, and commit the
files; ``tests/test_meshes.py`` fails while a file and its recipe differ.
"""

from __future__ import annotations

from pocket.meshes.files import write
from pocket.meshes.named import RECIPES, path


def main() -> None:
    for name, recipe in RECIPES.items():
        write(path(name), recipe())
        print(path(name))


if __name__ == "__main__":
    main()
