"""Shared fixtures for the projection tests."""

from __future__ import annotations
