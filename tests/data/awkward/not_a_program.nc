Toolpath export
This file lists the finishing pass.
