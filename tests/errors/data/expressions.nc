; Run errors of expressions at run time: each case ends at the error written after its line as ;### COL: message
; (tests/errors/test_error_goldens.py; pytest tests/errors --regen-goldens rewrites them)
---
#100 = [1/0]
;### 9: division by zero (1.0 / 0)
---
#100 = [1/[2-2]]
;### 9: division by zero (1.0 / 0)
---
#100 = [5 MOD 0]
;### 9: 5.0 MOD 0: division by zero
---
#100 = SQRT[-1]
;### 8: SQRT[-1.0]: the argument must not be negative
---
#100 = LN[0]
;### 8: LN[0.0]: the argument must be greater than 0
---
#100 = LN[-2]
;### 8: LN[-2.0]: the argument must be greater than 0
---
#100 = ACOS[1.5]
;### 8: ACOS[1.5]: the argument must lie between -1 and 1
---
#100 = ASIN[-1.0001]
;### 8: ASIN[-1.0001]: the argument must lie between -1 and 1
---
#100 = #0
;### 8: parameter #0 does not exist (valid: #1..#5999)
---
#100 = #6000
;### 8: parameter #6000 does not exist (valid: #1..#5999)
---
#100 = #[3000 * 2]
;### 8: parameter #6000 does not exist (valid: #1..#5999)
---
#100 = #[0 - 1]
;### 8: parameter #-1 does not exist (valid: #1..#5999)
---
#100 = #[2.5]
;### 8: parameter number 2.5 is not a whole number
---
#[6000] = 1
;### 1: parameter #6000 does not exist (valid: #1..#5999)
---
#100 = [[-8] ** 0.5]
;### 9: -8.0 ** 0.5: a negative number to a fractional power
---
#100 = [0 ** -1]
;### 9: 0.0 ** -1.0 has no finite value
---
#100 = EXP[1000]
;### 8: EXP[1000.0]: the result is too large
---
G0 X0
  G1 X[1/0] F100
;### 8: division by zero (1.0 / 0)
