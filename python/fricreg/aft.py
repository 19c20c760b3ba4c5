# SPDX-License-Identifier: GPL-3.0-or-later
"""(being written)"""

__all__ = []
