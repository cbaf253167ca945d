"""``python3 -m pointcloudsurface``: the pointcloud-surface command line."""
import sys

from pointcloudsurface.cli import main

sys.exit(main())
